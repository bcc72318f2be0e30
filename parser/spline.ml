(* POV-Ray's splines (math/splines.cpp semantics): entries sorted by
   parameter (a repeated parameter replaces the value), values stored as
   5-vectors, [terms] components returned (at least 2). *)

type kind = Linear | Quadratic | Cubic | Natural

type t = {
  kind : kind;
  pars : float array;
  vecs : float array array;  (** 5 components each *)
  terms : int;
}

let empty kind = { kind; pars = [||]; vecs = [||]; terms = 2 }
let kind_of_name = function
  | "linear_spline" -> Some Linear
  | "quadratic_spline" -> Some Quadratic
  | "cubic_spline" -> Some Cubic
  | "natural_spline" -> Some Natural
  | _ -> None

let with_kind s kind = { s with kind }
let length s = Array.length s.pars

let add s p ~terms v =
  let v = Array.init 5 (fun i -> if i < Array.length v then v.(i) else 0.) in
  let terms = max s.terms terms in
  match Array.find_index (fun q -> q = p) s.pars with
  | Some i ->
      let vecs = Array.copy s.vecs in
      vecs.(i) <- v;
      { s with vecs; terms }
  | None ->
      let n = Array.length s.pars in
      let i = ref 0 in
      while !i < n && s.pars.(!i) < p do incr i done;
      let ins a x = Array.init (n + 1) (fun j -> if j < !i then a.(j) else if j = !i then x else a.(j - 1)) in
      { s with pars = ins s.pars p; vecs = ins s.vecs v; terms }

(* The index of the first entry with a parameter above p (n past the
   end); 0 at or before the first. Inlined, as are the formulas below, so
   that the in-place evaluation passes no float to a call (a float passed
   to or returned from a function that is not inlined is boxed). *)
let[@inline] findt s p =
  let n = Array.length s.pars in
  if p <= s.pars.(0) then 0
  else if p >= s.pars.(n - 1) then n
  else begin
    let i = ref 0 in
    while s.pars.(!i) < p do incr i done;
    (* POV-Ray's search stops at the first entry >= p *)
    !i
  end

let[@inline] linear s i k p =
  let p1 = s.pars.(i) and p2 = s.pars.(i + 1) in
  let v1 = s.vecs.(i).(k) and v2 = s.vecs.(i + 1).(k) in
  ((p -. p1) *. (v2 -. v1) /. (p2 -. p1)) +. v1

let[@inline] quadratic s i k p =
  let p1 = s.pars.(i - 1) and p2 = s.pars.(i) and p3 = s.pars.(i + 1) in
  let v1 = s.vecs.(i - 1).(k) and v2 = s.vecs.(i).(k) and v3 = s.vecs.(i + 1).(k) in
  let n = (p2 -. p1) *. (p3 -. p1) *. (p3 -. p2) in
  let a = ((-.p2 *. v1) +. (p3 *. v1) +. (p1 *. v2) -. (p3 *. v2) -. (p1 *. v3) +. (p2 *. v3)) /. n in
  let b =
    ((p2 *. p2 *. v1) -. (p3 *. p3 *. v1) -. (p1 *. p1 *. v2) +. (p3 *. p3 *. v2) +. (p1 *. p1 *. v3)
    -. (p2 *. p2 *. v3))
    /. n
  in
  let c =
    ((-.p2 *. p2 *. p3 *. v1) +. (p2 *. p3 *. p3 *. v1) +. (p1 *. p1 *. p3 *. v2)
    -. (p1 *. p3 *. p3 *. v2) -. (p1 *. p1 *. p2 *. v3) +. (p1 *. p2 *. p2 *. v3))
    /. n
  in
  (((a *. p) +. b) *. p) +. c

(* Second-derivative coefficients of the natural cubic spline, per
   component (zero at both ends). *)
let natural_coeffs s =
  let n = Array.length s.pars in
  let co = Array.make_matrix n 5 0. in
  if n >= 3 then
    for k = 0 to 4 do
      let h = Array.make n 0. and b = Array.make n 0. and u = Array.make n 0. and v = Array.make n 0. in
      for i = 0 to n - 2 do
        h.(i) <- s.pars.(i + 1) -. s.pars.(i);
        b.(i) <- (s.vecs.(i + 1).(k) -. s.vecs.(i).(k)) /. h.(i)
      done;
      u.(1) <- 2. *. (h.(0) +. h.(1));
      v.(1) <- 6. *. (b.(1) -. b.(0));
      for i = 2 to n - 2 do
        u.(i) <- (2. *. (h.(i) +. h.(i - 1))) -. (h.(i - 1) *. h.(i - 1) /. u.(i - 1));
        v.(i) <- (6. *. (b.(i) -. b.(i - 1))) -. (h.(i - 1) *. v.(i - 1) /. u.(i - 1))
      done;
      for i = n - 2 downto 1 do
        co.(i).(k) <- (v.(i) -. (h.(i) *. co.(i + 1).(k))) /. u.(i)
      done
    done;
  co

let[@inline] natural s co i k p =
  let h = s.pars.(i + 1) -. s.pars.(i) in
  let d = p -. s.pars.(i) in
  let tmp = (co.(i).(k) /. 2.) +. (d *. (co.(i + 1).(k) -. co.(i).(k)) /. (6. *. h)) in
  let tmp =
    (-.(h /. 6.) *. (co.(i + 1).(k) +. (2. *. co.(i).(k))))
    +. ((s.vecs.(i + 1).(k) -. s.vecs.(i).(k)) /. h)
    +. (d *. tmp)
  in
  s.vecs.(i).(k) +. (d *. tmp)

(* Catmull-Rom on the segment (i, i + 1), the slopes of its neighbours'
   chords giving the tangents *)
let[@inline] catmull_rom s i k p =
  let p0 = s.pars.(i - 1) and p1 = s.pars.(i) and p2 = s.pars.(i + 1) and p3 = s.pars.(i + 2) in
  let v0 = s.vecs.(i - 1).(k) and v1 = s.vecs.(i).(k) and v2 = s.vecs.(i + 1).(k) and v3 = s.vecs.(i + 2).(k) in
  let dt = p2 -. p1 in
  let u = (p -. p1) /. dt in
  let before = (v1 -. v0) /. (p1 -. p0) and here = (v2 -. v1) /. (p2 -. p1) and after = (v3 -. v2) /. (p3 -. p2) in
  let dp0 = (before +. here) /. 2. *. dt in
  let dp1 = (after +. here) /. 2. *. dt in
  let u2 = u *. u in
  let u3 = u2 *. u in
  (v1 *. ((2. *. u3) -. (3. *. u2) +. 1.))
  +. (v2 *. ((3. *. u2) -. (2. *. u3)))
  +. (dp0 *. (u3 -. (2. *. u2) +. u))
  +. (dp1 *. (u3 -. u2))

let eval ?kind s p =
  let kind = Option.value kind ~default:s.kind in
  let n = Array.length s.pars in
  if n = 0 then invalid_arg "Spline.eval: empty spline";
  let last = n - 1 in
  let v =
    if last = 0 then Array.copy s.vecs.(0)
    else
      let i = findt s p in
      let co = if kind = Natural then natural_coeffs s else [||] in
      Array.init 5 (fun k ->
          match kind with
          | Linear -> if i = 0 then s.vecs.(0).(k) else if i > last then s.vecs.(last).(k) else linear s (i - 1) k p
          | Quadratic ->
              if i = 0 then s.vecs.(0).(k)
              else if i > last then s.vecs.(last).(k)
              else if last = 1 then linear s (i - 1) k p
              else if i > 1 then quadratic s (i - 1) k p
              else quadratic s i k p
          | Natural ->
              if i = 0 then s.vecs.(0).(k) else if i > last then s.vecs.(last).(k) else natural s co (i - 1) k p
          | Cubic ->
              if last = 1 then (s.vecs.(0).(k) +. s.vecs.(1).(k)) /. 2.
              else if i < 2 then s.vecs.(1).(k)
              else if i >= last then s.vecs.(last - 1).(k)
              else catmull_rom s (i - 1) k p)
  in
  Array.sub v 0 s.terms

(* A spline made ready for render-time calls: the natural spline's
   coefficients computed once here. *)
type fn = { spline : t; co : float array array }

let prepare s =
  if Array.length s.pars = 0 then invalid_arg "Spline.prepare: empty spline";
  { spline = s; co = (if s.kind = Natural then natural_coeffs s else [||]) }

let terms f = f.spline.terms

(* [eval]'s value, one component at a time: each case stores its value
   (a float joined from the cases could be boxed) *)
let component_into f (src : float array) si k (dst : float array) j =
  let s = f.spline in
  if k >= s.terms then dst.(j) <- 0.
  else
    let p = src.(si) in
    let last = Array.length s.pars - 1 in
    if last = 0 then dst.(j) <- s.vecs.(0).(k)
    else
      let i = findt s p in
      match s.kind with
      | Linear ->
          if i = 0 then dst.(j) <- s.vecs.(0).(k)
          else if i > last then dst.(j) <- s.vecs.(last).(k)
          else dst.(j) <- linear s (i - 1) k p
      | Quadratic ->
          if i = 0 then dst.(j) <- s.vecs.(0).(k)
          else if i > last then dst.(j) <- s.vecs.(last).(k)
          else if last = 1 then dst.(j) <- linear s (i - 1) k p
          else if i > 1 then dst.(j) <- quadratic s (i - 1) k p
          else dst.(j) <- quadratic s i k p
      | Natural ->
          if i = 0 then dst.(j) <- s.vecs.(0).(k)
          else if i > last then dst.(j) <- s.vecs.(last).(k)
          else dst.(j) <- natural s f.co (i - 1) k p
      | Cubic ->
          if last = 1 then dst.(j) <- (s.vecs.(0).(k) +. s.vecs.(1).(k)) /. 2.
          else if i < 2 then dst.(j) <- s.vecs.(1).(k)
          else if i >= last then dst.(j) <- s.vecs.(last - 1).(k)
          else dst.(j) <- catmull_rom s (i - 1) k p

let value f p =
  let src = [| p |] and a = Array.make f.spline.terms 0. in
  for k = 0 to Array.length a - 1 do
    component_into f src 0 k a k
  done;
  a
