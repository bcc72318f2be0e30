(* POV-Ray's polygon (see polygon.mli). The outlines are kept as edges in
   the plane's own coordinates (u, v from the first point): a hit is the
   plane's, kept when a ray from it along +u crosses an odd number of
   edges. *)

type t = {
  n : Vec3.t;  (** unit normal *)
  o : Vec3.t;  (** the first point *)
  u : Vec3.t;
  v : Vec3.t;  (** unit axes of the plane *)
  e : Float.Array.t;  (** per edge: u0, v0, u1, v1 *)
  lo : Vec3.t;
  hi : Vec3.t;
}

let edges p = Float.Array.length p.e / 4
let normal p = p.n
let point p = p.o
let bounds p = (p.lo, p.hi)

(* the outlines as point pairs: each ends where it returns to its start *)
let outlines (pts : Vec3.t array) =
  let n = Array.length pts in
  let pairs = ref [] and start = ref 0 and closed = ref true in
  let i = ref 1 in
  while !i < n do
    pairs := (pts.(!i - 1), pts.(!i)) :: !pairs;
    if pts.(!i) = pts.(!start) then begin
      (* the next outline starts after this point *)
      start := !i + 1;
      i := !i + 2
    end
    else incr i
  done;
  if !start < n then begin
    (* an outline left open: closed back to its start *)
    if n - !start >= 2 then pairs := (pts.(n - 1), pts.(!start)) :: !pairs;
    closed := false
  end;
  (List.rev !pairs, !closed)

let make (pts : Vec3.t array) =
  let n = Array.length pts in
  if n < 3 then Error (Printf.sprintf "a polygon needs at least 3 points, found %d" n)
  else
    let o = pts.(0) in
    (* the plane through the first point and the two others that span
       it best *)
    let size = Array.fold_left (fun m p -> Float.max m (Vec3.dist p o)) 0. pts in
    let best = ref Vec3.zero in
    for i = 1 to n - 1 do
      for j = i + 1 to n - 1 do
        let c = Vec3.cross (Vec3.sub pts.(i) o) (Vec3.sub pts.(j) o) in
        if Vec3.length c > Vec3.length !best then best := c
      done
    done;
    if size = 0. || Vec3.length !best <= 1e-12 *. size *. size then Error "the polygon's points are on one line"
    else
      let nv = Vec3.normalize !best in
      let off p = Float.abs (Vec3.dot nv (Vec3.sub p o)) in
      if Array.exists (fun p -> off p > 1e-6 *. Float.max 1. size) pts then
        Error "the polygon's points are not in one plane"
      else
        let pairs, closed = outlines pts in
        (* u along the first edge that has a length, v = n x u *)
        let u =
          match List.find_opt (fun (a, b) -> Vec3.dist a b > 0.) pairs with
          | Some (a, b) -> Vec3.normalize (Vec3.sub b a)
          | None -> Vec3.normalize (Vec3.sub pts.(1) o)
        in
        let u = Vec3.normalize (Vec3.sub u (Vec3.scale (Vec3.dot u nv) nv)) in
        let v = Vec3.cross nv u in
        let e = Float.Array.create (4 * List.length pairs) in
        List.iteri
          (fun k (a, b) ->
            let a = Vec3.sub a o and b = Vec3.sub b o in
            Float.Array.set e (4 * k) (Vec3.dot a u);
            Float.Array.set e ((4 * k) + 1) (Vec3.dot a v);
            Float.Array.set e ((4 * k) + 2) (Vec3.dot b u);
            Float.Array.set e ((4 * k) + 3) (Vec3.dot b v))
          pairs;
        let lo = Array.fold_left Vec3.min pts.(0) pts and hi = Array.fold_left Vec3.max pts.(0) pts in
        Ok ({ n = nv; o; u; v; e; lo; hi }, closed)

(* an odd number of edges crossed by the ray from (pu, pv) along +u *)
let covers p pu pv =
  let e = p.e in
  let odd = ref false in
  for k = 0 to (Float.Array.length e / 4) - 1 do
    let u0 = Float.Array.unsafe_get e (4 * k) and v0 = Float.Array.unsafe_get e ((4 * k) + 1)
    and u1 = Float.Array.unsafe_get e ((4 * k) + 2) and v1 = Float.Array.unsafe_get e ((4 * k) + 3) in
    if v0 > pv <> (v1 > pv) then
      let cu = u0 +. ((pv -. v0) *. (u1 -. u0) /. (v1 -. v0)) in
      if cu > pu then odd := not !odd
  done;
  !odd

let hit_s p (r : Ray.scratch) tmin (h : Hit.t) =
  let n = p.n and o = p.o in
  let dn = (r.dx *. n.x) +. (r.dy *. n.y) +. (r.dz *. n.z) in
  dn <> 0.
  &&
  let t = (((o.x -. r.ox) *. n.x) +. ((o.y -. r.oy) *. n.y) +. ((o.z -. r.oz) *. n.z)) /. dn in
  t > tmin && t > h.floor && t < h.t
  &&
  let px = r.ox +. (t *. r.dx) -. o.x and py = r.oy +. (t *. r.dy) -. o.y and pz = r.oz +. (t *. r.dz) -. o.z in
  let u = p.u and v = p.v in
  covers p ((px *. u.x) +. (py *. u.y) +. (pz *. u.z)) ((px *. v.x) +. (py *. v.y) +. (pz *. v.z))
  && begin
       h.t <- t;
       h.id <- 0.;
       true
     end
