(* Isosurfaces (see isosurface.mli), searched as POV-Ray describes its
   method (checked with its trace()): halving the ray's stretch in the container, a half dropped
   when f(a) + f(b) >= max_gradient * (b - a) (the function cannot reach
   the threshold between a and b if its slope is below max_gradient),
   down to stretches of at most accuracy, the hit at the end of the
   first one whose end is inside. *)

type container = Box of Vec3.t * Vec3.t | Sphere of Vec3.t * float

type fn = { result : int; run : float array -> unit; frames : float array Scratch.key }

let fn ~slots ~result run =
  if slots < 3 || result < 0 || result >= slots then invalid_arg "Isosurface.fn: bad slot counts";
  { result; run; frames = Scratch.key (fun () -> Array.make slots 0.) }

let fn_of_closure f = fn ~slots:4 ~result:3 (fun s -> Array.unsafe_set s 3 (f s.(0) s.(1) s.(2)))

type t = {
  f : fn;
  container : container;
  lo : Vec3.t;  (* a box container's corners, ordered *)
  hi : Vec3.t;
  threshold : float;
  accuracy : float;
  max_gradient : float;
  open_ : bool;
  max_trace : int;
  stack : Float.Array.t Scratch.key;  (* the halves still to look at *)
}

(* levels of halving kept; a stretch 2^60 times the accuracy is never met *)
let max_levels = 64

let make ~fn ~container ~threshold ~accuracy ~max_gradient ~open_ ~max_trace =
  if not (accuracy > 0. && max_gradient > 0. && max_trace >= 1) then invalid_arg "Isosurface.make";
  let lo, hi =
    match container with
    | Box (a, b) -> (Vec3.min a b, Vec3.max a b)
    | Sphere (c, r) ->
        let e = Vec3.make r r r in
        (Vec3.sub c e, Vec3.add c e)
  in
  { f = fn; container; lo; hi; threshold; accuracy; max_gradient; open_; max_trace;
    stack = Scratch.key (fun () -> Float.Array.make (4 * (max_levels + 2)) 0.) }

let[@inline] eval t x y z =
  let s = Scratch.get t.f.frames in
  Array.unsafe_set s 0 x;
  Array.unsafe_set s 1 y;
  Array.unsafe_set s 2 z;
  t.f.run s;
  Array.unsafe_get s t.f.result -. t.threshold

let value t x y z = eval t x y z

let in_container t x y z =
  match t.container with
  | Box _ -> x >= t.lo.x && x <= t.hi.x && y >= t.lo.y && y <= t.hi.y && z >= t.lo.z && z <= t.hi.z
  | Sphere (c, r) ->
      let px = x -. c.x and py = y -. c.y and pz = z -. c.z in
      (px *. px) +. (py *. py) +. (pz *. pz) <= r *. r

(* POV-Ray: inside the container and not above the threshold *)
let inside t x y z = in_container t x y z && not (eval t x y z > 0.)

(* Where a search may start, as close to the ray's origin as a hit can
   be (POV-Ray's isosurface tolerance) *)
let tolerance = 1e-6

(* a crossing closer than this many accuracies to a search started on the
   surface is the surface the ray leaves (fitted to POV-Ray's pictures:
   its speckled self-shadow near a sphere's terminator, 48.9 dB at
   160x120 with 5, 44.2 with 10, 35.1 with 3) *)
let skip_factor = 5.

(* The parts hit: the function's surface, a box container's faces (as
   Shape's boxes number them, plus 1), a sphere container *)
let id_surface = 0.
let id_sphere = 7.

(* The first crossing of the threshold on [a, b] of the ray p + s u
   (unit u), with the function's sign [sg] (so that sg f(a) >= 0), or
   nan. POV-Ray's search, depth first and left first: a stack of the
   right halves still to look at, 4 floats each (start, value, end
   value, length), so that nothing is allocated. *)
let[@inline] eval_ray t px py pz ux uy uz s = eval t (px +. (s *. ux)) (py +. (s *. uy)) (pz +. (s *. uz))

let find_root t sg px py pz ux uy uz a fa b fb =
  let st = Scratch.get t.stack in
  let maxg = t.max_gradient and acc = t.accuracy in
  Float.Array.unsafe_set st 0 a;
  Float.Array.unsafe_set st 1 fa;
  Float.Array.unsafe_set st 2 fb;
  Float.Array.unsafe_set st 3 (b -. a);
  let n = ref 1 and result = ref Float.nan in
  while !n > 0 do
    decr n;
    let k = 4 * !n in
    let a = Float.Array.unsafe_get st k
    and fa = Float.Array.unsafe_get st (k + 1)
    and fb = Float.Array.unsafe_get st (k + 2)
    and w = Float.Array.unsafe_get st (k + 3) in
    if fa +. fb -. (maxg *. w) < 0. then begin
      if w > acc && !n < max_levels then begin
        let w = 0.5 *. w in
        let m = a +. w in
        let fm = sg *. eval_ray t px py pz ux uy uz m in
        (* the right half below the left one, which is looked at first *)
        Float.Array.unsafe_set st k m;
        Float.Array.unsafe_set st (k + 1) fm;
        Float.Array.unsafe_set st (k + 2) fb;
        Float.Array.unsafe_set st (k + 3) w;
        Float.Array.unsafe_set st (k + 4) a;
        Float.Array.unsafe_set st (k + 5) fa;
        Float.Array.unsafe_set st (k + 6) fm;
        Float.Array.unsafe_set st (k + 7) w;
        n := !n + 2
      end
      else if fb <= 0. then begin
        (* a stretch no longer than the accuracy, across the threshold:
           its end *)
        result := a +. w;
        n := 0
      end
    end
  done;
  !result

(* The ray's stretch in the container, in units of the unit direction:
   entry, exit and the parts crossed there; false when it misses *)
type span = { mutable s1 : float; mutable s2 : float; mutable side1 : float; mutable side2 : float }

let span_key = Scratch.key (fun () -> { s1 = 0.; s2 = 0.; side1 = 0.; side2 = 0. })

let slab sp o d l u axis =
  if d = 0. then (if o < l || o > u then sp.s1 <- infinity)
  else begin
    let p = (l -. o) /. d and q = (u -. o) /. d in
    (* faces numbered 1 + 2 axis (low) and 2 + 2 axis (high) *)
    if p < q then begin
      if p > sp.s1 then (sp.s1 <- p; sp.side1 <- (2. *. axis) +. 1.);
      if q < sp.s2 then (sp.s2 <- q; sp.side2 <- (2. *. axis) +. 2.)
    end
    else begin
      if q > sp.s1 then (sp.s1 <- q; sp.side1 <- (2. *. axis) +. 2.);
      if p < sp.s2 then (sp.s2 <- p; sp.side2 <- (2. *. axis) +. 1.)
    end
  end

let container_span t sp px py pz ux uy uz =
  match t.container with
  | Box _ ->
      sp.s1 <- neg_infinity;
      sp.s2 <- infinity;
      sp.side1 <- id_surface;
      sp.side2 <- id_surface;
      slab sp px ux t.lo.x t.hi.x 0.;
      slab sp py uy t.lo.y t.hi.y 1.;
      slab sp pz uz t.lo.z t.hi.z 2.;
      sp.s1 <= sp.s2
  | Sphere (c, r) ->
      let ox = px -. c.x and oy = py -. c.y and oz = pz -. c.z in
      let hb = (ox *. ux) +. (oy *. uy) +. (oz *. uz) in
      let cc = (ox *. ox) +. (oy *. oy) +. (oz *. oz) -. (r *. r) in
      let disc = (hb *. hb) -. cc in
      if disc < 0. then false
      else begin
        let sq = Float.sqrt disc in
        sp.s1 <- -.hb -. sq;
        sp.s2 <- -.hb +. sq;
        sp.side1 <- id_sphere;
        sp.side2 <- id_sphere;
        true
      end

(* record a hit at [s] (unit-direction units) when it lies in (lo, up) *)
let[@inline] take (h : Hit.t) len lo up s id =
  if s > lo && s < up then begin
    h.t <- s /. len;
    h.id <- id;
    true
  end
  else false

let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let lower = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let len = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let ux = r.dx /. len and uy = r.dy /. len and uz = r.dz /. len in
  let px = r.ox and py = r.oy and pz = r.oz in
  let sp = Scratch.get span_key in
  if not (container_span t sp px py pz ux uy uz) then false
  else begin
    let s1 = sp.s1 and s2 = sp.s2 in
    (* hits in units of the unit direction: beyond [lo], before [up] *)
    let lo = lower *. len and up = h.t *. len in
    if s2 < tolerance then false
    else if (not t.open_) && s1 > tolerance && eval_ray t px py pz ux uy uz s1 < 0. then
      (* the container's surface, where the function is inside at it:
         nothing can be nearer *)
      take h len lo up s1 sp.side1
    else begin
      let found = ref false and stop = ref false in
      let a = ref (if s1 > tolerance then s1 else tolerance) and count = ref 0 in
      while (not !stop) && s2 -. !a >= t.accuracy && !count < t.max_trace do
        let fa = eval_ray t px py pz ux uy uz !a in
        (* below the threshold where the search starts: look for where
           the function rises above it *)
        let sg = if fa < 0. then -1. else 1. in
        (* a search from the ray's origin with the function within
           max_gradient * accuracy of the threshold: a ray leaving the
           surface *)
        let on_surface = Float.abs fa < t.max_gradient *. t.accuracy && !a <= tolerance in
        let root = find_root t sg px py pz ux uy uz !a (sg *. fa) s2 (sg *. eval_ray t px py pz ux uy uz s2) in
        if Float.is_nan root then stop := true
        else if on_surface && root -. !a <= skip_factor *. t.accuracy then
          (* the surface the ray leaves: looked past *)
          a := root
        else begin
          incr count;
          if root > lo then begin
            found := take h len lo up root id_surface;
            stop := true
          end
          else a := root
        end
      done;
      if !found then true
      else if (not t.open_) && s2 < infinity && eval_ray t px py pz ux uy uz s2 < 0. then
        take h len lo up s2 sp.side2
      else false
    end
  end

(* POV-Ray's normal: a box container's faces their own; the function's
   gradient elsewhere, on a sphere container's surface too (a constant
   function's gradient, zero, gives +x) *)
let normal_into t (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  match int_of_float h.id with
  | 1 -> Vec3.set out (-1.) 0. 0.
  | 2 -> Vec3.set out 1. 0. 0.
  | 3 -> Vec3.set out 0. (-1.) 0.
  | 4 -> Vec3.set out 0. 1. 0.
  | 5 -> Vec3.set out 0. 0. (-1.)
  | 6 -> Vec3.set out 0. 0. 1.
  | _ ->
      let x = p.mx and y = p.my and z = p.mz and d = t.accuracy in
      let f0 = eval t x y z in
      let gx = eval t (x +. d) y z -. f0 in
      let gy = eval t x (y +. d) z -. f0 in
      let gz = eval t x y (z +. d) -. f0 in
      if gx = 0. && gy = 0. && gz = 0. then Vec3.set out 1. 0. 0.
      else begin
        Vec3.set out gx gy gz;
        Vec3.normalize_m out
      end

let bounds t = (t.lo, t.hi)
