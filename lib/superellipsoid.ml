(* Superellipsoids (see superellipsoid.mli), with POV-Ray's algorithm and
   constants. *)

type t = { ex : float; ez : float }  (* the powers 2/e and 2/n *)

let make e n = { ex = 2. /. e; ez = 2. /. n }
let bounds = (Vec3.make (-1.0001) (-1.0001) (-1.0001), Vec3.make 1.0001 1.0001 1.0001)

let zero_tolerance = 1e-10
let depth_tolerance = 1e-4
let epsilon = 1e-10
let min_value = -1.01
let max_value = 1.01
let max_iterations = 20

(* x^e, exact for small whole powers as POV-Ray's *)
let power x e =
  if Float.of_int (Float.to_int e) = e then
    match Float.to_int e with
    | 0 -> 1.
    | 1 -> x
    | 2 -> x *. x
    | 3 -> x *. x *. x
    | 4 -> let b = x *. x in b *. b
    | 5 -> let b = x *. x in b *. b *. x
    | 6 -> let b = x *. x in b *. b *. b
    | _ -> Float.pow x e
  else Float.pow x e

(* (x^e + y^e)^(1/e), written to keep its range *)
let g x y e =
  if x > y then begin
    let v = 1. +. power (y /. x) e in
    (if v <> 1. then Float.pow v (1. /. e) else v) *. x
  end
  else if y <> 0. then begin
    let v = 1. +. power (x /. y) e in
    (if v <> 1. then Float.pow v (1. /. e) else v) *. y
  end
  else 0.

let value s x y z = g (g (Float.abs x) (Float.abs y) s.ex) (Float.abs z) s.ez -. 1.

(* POV-Ray's inside: below its EPSILON (1e-10) *)
let inside s x y z = value s x y z < 1e-10

(* Per domain, one float array (floats passed to functions that are not
   inlined, or returned by them, would be boxed): the ray's stretch cut at
   the nine planes (11 slots), then the slots below. *)
let s_lo = 11 (* the ray's stretch in the box *)
let s_hi = 12
let s_ray = 13 (* px py pz dx dy dz: the ray, its direction unit *)
let s_t0 = 19 (* a bracket: t0 v0 t1 v1 *)
let s_result = 23

let work_key = Scratch.key (fun () -> Float.Array.make 24 0.)

let planes = [| (1., 1., 0.); (1., -1., 0.); (1., 0., 1.); (1., 0., -1.); (0., 1., 1.); (0., 1., -1.); (1., 0., 0.);
                (0., 1., 0.); (0., 0., 1.) |]

let[@inline] get w i = Float.Array.unsafe_get w i
let[@inline] set w i v = Float.Array.unsafe_set w i v

(* the superellipsoid's value at [t] along the ray in [w] *)
let[@inline] at s w t =
  value s (get w s_ray +. (t *. get w (s_ray + 3))) (get w (s_ray + 1) +. (t *. get w (s_ray + 4)))
    (get w (s_ray + 2) +. (t *. get w (s_ray + 5)))

(* one axis of the box: the ray's stretch in [w] narrowed to its slab;
   false when the ray runs beside it *)
let[@inline] slab w p d =
  if Float.abs d > epsilon then begin
    let a = (min_value -. p) /. d and b = (max_value -. p) /. d in
    (* one comparison each ([Float.min] calls C for the sign of a
       zero): [d] is not zero, so neither end is a nan *)
    set w s_lo (Floats.fmax (get w s_lo) (Floats.fmin a b));
    set w s_hi (Floats.fmin (get w s_hi) (Floats.fmax a b));
    true
  end
  else not (p < min_value || p > max_value)

(* the stretch of the ray in the box [min_value, max_value]^3, into the
   [s_lo] and [s_hi] slots of [w]; false when there is none *)
let box_stretch w =
  set w s_lo neg_infinity;
  set w s_hi infinity;
  let px = get w s_ray and py = get w (s_ray + 1) and pz = get w (s_ray + 2) in
  let ok = slab w px (get w (s_ray + 3)) in
  let ok = slab w py (get w (s_ray + 4)) && ok in
  let ok = slab w pz (get w (s_ray + 5)) && ok in
  ok && get w s_lo <= get w s_hi && get w s_hi >= epsilon

(* secant and bisection steps between samples of opposite signs (the
   bracket in [w]): the distance of the point found, into [s_result] *)
let solve_hit1 s w =
  let t0 = ref (get w s_t0) and v0 = ref (get w (s_t0 + 1)) and t1 = ref (get w (s_t0 + 2))
  and v1 = ref (get w (s_t0 + 3)) and result = ref nan and i = ref 0 in
  while Float.is_nan !result && !i < max_iterations do
    if Float.abs !v0 < zero_tolerance then result := !t0
    else if Float.abs !v1 < zero_tolerance then result := !t1
    else begin
      let x = Float.abs !v0 /. Float.abs (!v1 -. !v0) in
      let t2 = !t0 +. (x *. (!t1 -. !t0)) in
      let v2 = at s w t2 in
      let t3 = !t0 +. (0.5 *. (!t1 -. !t0)) in
      let v3 = at s w t3 in
      if v2 *. v3 < 0. then begin
        t0 := t2; v0 := v2; t1 := t3; v1 := v3
      end
      else if Float.abs v2 < Float.abs v3 then begin
        if !v0 *. v2 < 0. then (t1 := t2; v1 := v2) else (t0 := t2; v0 := v2)
      end
      else if !v0 *. v3 < 0. then (t1 := t3; v1 := v3)
      else (t0 := t3; v0 := v3)
    end;
    incr i
  done;
  set w s_result (if Float.is_nan !result then if Float.abs !v0 < Float.abs !v1 then !t0 else !t1 else !result)

(* no sign change between two samples (t0 v0 t1 of the bracket in [w]):
   Newton's method from the first, as POV-Ray tries it; the distance
   found, or nan, into [s_result] *)
let check_hit2 s w =
  let t0 = get w s_t0 and t1 = get w (s_t0 + 2) in
  let dt0 = ref t0 and dt1 = ref (t0 +. (0.0001 *. (t1 -. t0))) and v0 = ref (get w (s_t0 + 1)) in
  let maxdelta = t1 -. t0 in
  let result = ref nan and go = ref true and i = ref 0 in
  while !go && !dt0 < t1 && !i < max_iterations do
    let v1 = at s w !dt1 in
    if !v0 *. v1 < 0. then begin
      set w s_t0 !dt0;
      set w (s_t0 + 1) !v0;
      set w (s_t0 + 2) !dt1;
      set w (s_t0 + 3) v1;
      solve_hit1 s w;
      result := get w s_result;
      go := false
    end
    else if Float.abs v1 < zero_tolerance then begin
      result := !dt1;
      go := false
    end
    else if (!v0 > 0. && v1 > !v0) || (!v0 < 0. && v1 < !v0) || v1 = !v0 then go := false
    else begin
      let deltat = v1 *. (!dt1 -. !dt0) /. (v1 -. !v0) in
      if Float.abs deltat > maxdelta then go := false
      else begin
        v0 := v1;
        dt0 := !dt1;
        dt1 := !dt1 -. deltat
      end
    end;
    incr i
  done;
  set w s_result !result

(* [t] (in units of the unit direction) recorded in [h] when it is
   nearer and beyond [tmin] *)
let[@inline] accept (h : Hit.t) tmin len t =
  (* distances in units of the ray's own direction *)
  let t' = t /. len in
  if t' > tmin && t' < h.t && t' *. len > depth_tolerance then begin
    h.t <- t';
    h.id <- 0.;
    true
  end
  else false

let hit_s s (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let len = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let dx = r.dx /. len and dy = r.dy /. len and dz = r.dz /. len in
  let px = r.ox and py = r.oy and pz = r.oz in
  let w = Scratch.get work_key in
  set w s_ray px;
  set w (s_ray + 1) py;
  set w (s_ray + 2) pz;
  set w (s_ray + 3) dx;
  set w (s_ray + 4) dy;
  set w (s_ray + 5) dz;
  if not (box_stretch w) then false
  else begin
    let t1 = Float.max (get w s_lo) depth_tolerance and t2 = get w s_hi in
    (* the stretch cut at the nine planes, a little widened as POV-Ray
       does; sorted in place *)
    let widen = epsilon *. (t2 -. t1) in
    set w 0 t1;
    set w 1 t2;
    let n = ref 2 in
    for k = 0 to Array.length planes - 1 do
      let a, b, c = Array.unsafe_get planes k in
      let d = (dx *. a) +. (dy *. b) +. (dz *. c) in
      if Float.abs d >= epsilon then begin
        let t = -.((px *. a) +. (py *. b) +. (pz *. c)) /. d in
        if t >= t1 -. widen && t <= t2 +. widen then begin
          set w !n t;
          incr n
        end
      end
    done;
    let n = !n in
    Floats.sort_prefix w n;
    let found = ref false and stop = ref false in
    let v0 = ref (at s w (get w 0)) in
    if Float.abs !v0 < zero_tolerance && accept h tmin len (get w 0) then found := true;
    let i = ref 1 in
    while (not !found) && (not !stop) && !i < n do
      let v1 = at s w (get w !i) in
      (if Float.abs v1 < zero_tolerance then (if accept h tmin len (get w !i) then found := true)
       else begin
         set w s_t0 (get w (!i - 1));
         set w (s_t0 + 1) !v0;
         set w (s_t0 + 2) (get w !i);
         set w (s_t0 + 3) v1;
         if !v0 *. v1 < 0. then begin
           solve_hit1 s w;
           if accept h tmin len (get w s_result) then found := true
         end
         else begin
           check_hit2 s w;
           let t = get w s_result in
           if not (Float.is_nan t) then if accept h tmin len t then found := true else stop := true
         end
       end);
      v0 := v1;
      incr i
    done;
    !found
  end

let normal_into s (p : Vec3.m) (out : Vec3.m) =
  let x = p.mx and y = p.my and z = p.mz in
  let z2n = if z <> 0. then power (Float.abs z) s.ez else 0. in
  let nz = if z <> 0. then z2n /. z else 0. in
  let r = ref 0. and nx = ref x and ny = ref y in
  if Float.abs x > Float.abs y then begin
    r := power (Float.abs (y /. x)) s.ex;
    nx := (1. -. z2n) /. x;
    ny := if y <> 0. then (1. -. z2n) *. !r /. y else 0.
  end
  else if y <> 0. then begin
    r := power (Float.abs (x /. y)) s.ex;
    nx := if x <> 0. then (1. -. z2n) *. !r /. x else 0.;
    ny := (1. -. z2n) /. y
  end;
  let nz = if z <> 0. then nz *. (1. +. !r) else nz in
  Vec3.set out !nx !ny nz;
  if out.mx = 0. && out.my = 0. && out.mz = 0. then Vec3.set out 0. 0. 1. else Vec3.normalize_m out
