(* Extruded TrueType text (see text.mli). Every outline piece is stored as
   a quadratic Bezier (a line's control point at its middle), 6 floats:
   start, control, end. *)

type t = {
  segs : Float.Array.t;  (* 6 per piece *)
  first : int array;  (* per glyph: its first piece, then one past its last *)
  boxes : Float.Array.t;  (* per glyph: xmin, ymin, xmax, ymax *)
  thickness : float;
  lo : Vec3.t;
  hi : Vec3.t;
}

let glyph_count t = Array.length t.first - 1
let thickness t = t.thickness
let bounds t = (t.lo, t.hi)

let make_codes font codes ~thickness ~(offset : Vec3.t) =
  let f = 1. /. float (Ttf.units_per_em font) in
  let pieces = ref [] and firsts = ref [ 0 ] and boxes = ref [] and count = ref 0 in
  let total_x = ref 0. and total_y = ref 0. and last = ref 0 in
  Array.iteri
    (fun i code ->
      let g = Ttf.glyph_index font code in
      let gl = Ttf.glyph font g in
      let aw = float (Ttf.advance font g) and lsb = float (Ttf.lsb font g) in
      (* POV-Ray's setting: the first glyph's left edge at 0, then each
         at the previous advance, its bearing and the pair's kerning *)
      let tx, ty =
        if i = 0 then begin
          let tx = -.gl.xmin *. f in
          total_x := (aw -. lsb) *. f;
          (tx, 0.)
        end
        else begin
          let k = float (Ttf.kerning font !last g) in
          let tx = !total_x +. ((lsb -. gl.xmin +. k) *. f) in
          total_x := !total_x +. ((aw +. k) *. f);
          (tx, !total_y)
        end
      in
      total_x := !total_x +. offset.x;
      total_y := !total_y +. offset.y;
      last := g;
      let px x = (x *. f) +. tx and py y = (y *. f) +. ty in
      let bx0 = ref infinity and by0 = ref infinity and bx1 = ref neg_infinity and by1 = ref neg_infinity in
      let add x0 y0 qx qy x1 y1 =
        List.iter
          (fun (x, y) ->
            bx0 := Float.min !bx0 x;
            by0 := Float.min !by0 y;
            bx1 := Float.max !bx1 x;
            by1 := Float.max !by1 y)
          [ (x0, y0); (qx, qy); (x1, y1) ];
        pieces := [ x0; y0; qx; qy; x1; y1 ] :: !pieces;
        incr count
      in
      Array.iter
        (Array.iter (function
          | Ttf.Line (x0, y0, x1, y1) ->
              let x0 = px x0 and y0 = py y0 and x1 = px x1 and y1 = py y1 in
              add x0 y0 ((x0 +. x1) /. 2.) ((y0 +. y1) /. 2.) x1 y1
          | Ttf.Quad (x0, y0, qx, qy, x1, y1) -> add (px x0) (py y0) (px qx) (py qy) (px x1) (py y1)))
        gl.contours;
      firsts := !count :: !firsts;
      boxes := [ !bx0; !by0; !bx1; !by1 ] :: !boxes)
    codes;
  let segs = Float.Array.of_list (List.concat (List.rev !pieces)) in
  let boxes = Float.Array.of_list (List.concat (List.rev !boxes)) in
  let n = Float.Array.length boxes / 4 in
  let lo = ref (Vec3.make infinity infinity 0.) and hi = ref (Vec3.make neg_infinity neg_infinity thickness) in
  for g = 0 to n - 1 do
    let b k = Float.Array.get boxes ((4 * g) + k) in
    if b 0 <= b 2 then begin
      lo := Vec3.make (Float.min !lo.x (b 0)) (Float.min !lo.y (b 1)) 0.;
      hi := Vec3.make (Float.max !hi.x (b 2)) (Float.max !hi.y (b 3)) thickness
    end
  done;
  let lo, hi = if !lo.x <= !hi.x then (!lo, !hi) else (Vec3.zero, Vec3.make 0. 0. thickness) in
  { segs; first = Array.of_list (List.rev !firsts); boxes; thickness; lo; hi }

let make font s ~thickness ~offset = make_codes font (Array.init (String.length s) (fun i -> Char.code s.[i])) ~thickness ~offset

let[@inline] g a i = Float.Array.unsafe_get a i

(* The roots in [0, 1) of a s^2 + b s + c, into the scratch (count
   returned): the stable form of the formula, a line's when a is nil *)
let[@inline] keep (out : Float.Array.t) n s =
  if s >= 0. && s < 1. then begin
    Float.Array.unsafe_set out n s;
    n + 1
  end
  else n

let roots (out : Float.Array.t) a b c =
  let n = ref 0 in
  let scale = Float.max (Float.abs b) (Float.abs c) in
  if Float.abs a <= 1e-12 *. scale then (if b <> 0. then n := keep out !n (-.c /. b))
  else begin
    let disc = (b *. b) -. (4. *. a *. c) in
    if disc >= 0. then begin
      let q = -0.5 *. (b +. (if b >= 0. then Float.sqrt disc else -.Float.sqrt disc)) in
      if q <> 0. then begin
        n := keep out !n (q /. a);
        n := keep out !n (c /. q)
      end
      else n := keep out !n 0.
    end
  end;
  !n

let roots_key = Scratch.key (fun () -> Float.Array.make 2 0.)

(* nonzero winding of glyph [k]'s outlines around (x, y): crossings of
   the half-line to +x, signed by the direction the outline crosses it;
   a piece owns its start and not its end, so a shared end counts once *)
let glyph_winding t k x y =
  let r = Scratch.get roots_key in
  let w = ref 0 in
  for i = t.first.(k) to t.first.(k + 1) - 1 do
    let o = 6 * i in
    let y0 = g t.segs (o + 1) and qy = g t.segs (o + 3) and y1 = g t.segs (o + 5) in
    if not ((y < y0 && y < qy && y < y1) || (y > y0 && y > qy && y > y1)) then begin
      let x0 = g t.segs o and qx = g t.segs (o + 2) and x1 = g t.segs (o + 4) in
      let ay = y0 -. (2. *. qy) +. y1 and by = 2. *. (qy -. y0) in
      let n = roots r ay by (y0 -. y) in
      for j = 0 to n - 1 do
        let s = Float.Array.unsafe_get r j in
        let xs = (((x0 -. (2. *. qx) +. x1) *. s) +. (2. *. (qx -. x0))) *. s +. x0 in
        let dy = (2. *. ay *. s) +. by in
        (* a piece ending exactly at this height leaves that crossing to
           the next piece, which starts there *)
        if xs > x && dy <> 0. && not (y1 = y && s > 0.5) then w := !w + if dy > 0. then 1 else -1
      done
    end
  done;
  !w

let winding t x y =
  let w = ref 0 in
  for k = 0 to glyph_count t - 1 do
    w := !w + glyph_winding t k x y
  done;
  !w

let in_glyph t k x y =
  x >= g t.boxes (4 * k)
  && x <= g t.boxes ((4 * k) + 2)
  && y >= g t.boxes ((4 * k) + 1)
  && y <= g t.boxes ((4 * k) + 3)
  && glyph_winding t k x y <> 0

(* whether a glyph from the [k]th on holds (x, y) (a loop: a local
   function would be a closure made at every test) *)
let in_any_glyph t x y =
  let k = ref 0 and found = ref false in
  while (not !found) && !k < glyph_count t do
    if in_glyph t !k x y then found := true;
    incr k
  done;
  !found

let inside t x y z = z > 0. && z < t.thickness && in_any_glyph t x y

(* whether the ray misses glyph [k]'s box (x, y, and z from 0 to the
   thickness) within (tmin, tmax): written out, a tuple per slab would be
   allocated per glyph and ray *)
let box_missed t k (r : Ray.scratch) tmin tmax =
  let b0 = g t.boxes (4 * k) and b1 = g t.boxes ((4 * k) + 1) and b2 = g t.boxes ((4 * k) + 2)
  and b3 = g t.boxes ((4 * k) + 3) in
  let t0 = ref tmin and t1 = ref tmax and miss = ref false in
  if r.dx = 0. then (if r.ox < b0 || r.ox > b2 then miss := true)
  else begin
    let a = (b0 -. r.ox) /. r.dx and c = (b2 -. r.ox) /. r.dx in
    t0 := Float.max !t0 (Float.min a c);
    t1 := Float.min !t1 (Float.max a c)
  end;
  if r.dy = 0. then (if r.oy < b1 || r.oy > b3 then miss := true)
  else begin
    let a = (b1 -. r.oy) /. r.dy and c = (b3 -. r.oy) /. r.dy in
    t0 := Float.max !t0 (Float.min a c);
    t1 := Float.min !t1 (Float.max a c)
  end;
  if r.dz = 0. then (if r.oz < 0. || r.oz > t.thickness then miss := true)
  else begin
    let a = -.r.oz /. r.dz and c = (t.thickness -. r.oz) /. r.dz in
    t0 := Float.max !t0 (Float.min a c);
    t1 := Float.min !t1 (Float.max a c)
  end;
  !miss || !t0 > !t1


let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let found = ref false in
  let rs = Scratch.get roots_key in
  let d2 = (r.dx *. r.dx) +. (r.dy *. r.dy) in
  for k = 0 to glyph_count t - 1 do
    if not (box_missed t k r tmin h.t) then begin
      (* the two faces *)
      if r.dz <> 0. then begin
        let tf = -.r.oz /. r.dz in
        if tf > tmin && tf < h.t && in_glyph t k (r.ox +. (tf *. r.dx)) (r.oy +. (tf *. r.dy)) then
          if Hit.keep h tmin tf 0. 0. then found := true;
        let tb = (t.thickness -. r.oz) /. r.dz in
        if tb > tmin && tb < h.t && in_glyph t k (r.ox +. (tb *. r.dx)) (r.oy +. (tb *. r.dy)) then
          if Hit.keep h tmin tb 1. 0. then found := true
      end;
      (* the swept outline: where the ray's shadow on the plane crosses a
         piece, at a height between the faces *)
      if d2 > 0. then
        for i = t.first.(k) to t.first.(k + 1) - 1 do
          let o = 6 * i in
          let x0 = g t.segs o and y0 = g t.segs (o + 1) and qx = g t.segs (o + 2) and qy = g t.segs (o + 3)
          and x1 = g t.segs (o + 4) and y1 = g t.segs (o + 5) in
          let ax = x0 -. (2. *. qx) +. x1 and ay = y0 -. (2. *. qy) +. y1 in
          let bx = 2. *. (qx -. x0) and by = 2. *. (qy -. y0) in
          (* cross (B(s) - o, d) = 0 *)
          let a = (ax *. r.dy) -. (ay *. r.dx) and b = (bx *. r.dy) -. (by *. r.dx)
          and c = ((x0 -. r.ox) *. r.dy) -. ((y0 -. r.oy) *. r.dx) in
          let n = roots rs a b c in
          for j = 0 to n - 1 do
            let s = Float.Array.unsafe_get rs j in
            let px = (((ax *. s) +. bx) *. s) +. x0 and py = (((ay *. s) +. by) *. s) +. y0 in
            let tt = (((px -. r.ox) *. r.dx) +. ((py -. r.oy) *. r.dy)) /. d2 in
            let z = r.oz +. (tt *. r.dz) in
            if z >= 0. && z <= t.thickness && Hit.keep h tmin tt (float (i + 2)) s then found := true
          done
        done
    end
  done;
  !found

let normal_into t (h : Hit.t) (out : Vec3.m) =
  if h.id = 0. then Vec3.set out 0. 0. (-1.)
  else if h.id = 1. then Vec3.set out 0. 0. 1.
  else begin
    let o = 6 * (int_of_float h.id - 2) and s = h.u in
    let x0 = g t.segs o and y0 = g t.segs (o + 1) and qx = g t.segs (o + 2) and qy = g t.segs (o + 3)
    and x1 = g t.segs (o + 4) and y1 = g t.segs (o + 5) in
    let tx = (2. *. (x0 -. (2. *. qx) +. x1) *. s) +. (2. *. (qx -. x0))
    and ty = (2. *. (y0 -. (2. *. qy) +. y1) *. s) +. (2. *. (qy -. y0)) in
    (* TrueType fills to the right of an outline's direction: outward is
       to its left *)
    let l = Float.sqrt ((tx *. tx) +. (ty *. ty)) in
    if l = 0. then Vec3.set out 1. 0. 0. else Vec3.set out (-.ty /. l) (tx /. l) 0.
  end
