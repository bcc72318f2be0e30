type t = {
  w : int;
  h : int;
  once : bool;
  interpolate : int;
  by_index : bool;
  map_type : int;
  heights : Float.Array.t;
}

let make ?(map_type = 0) ~w ~h ~once ~interpolate ~by_index heights =
  if w <= 0 || h <= 0 || Float.Array.length heights <> w * h then invalid_arg "Bump_map.make: size";
  if interpolate <> 0 && interpolate <> 2 && interpolate <> 4 then invalid_arg "Bump_map.make: interpolate";
  { w; h; once; interpolate; by_index; map_type; heights }

let grey r g b = (0.297 *. r) +. (0.589 *. g) +. (0.114 *. b)

(* the pixel column (or row) of a coordinate: clamped to the image when
   [once], else wrapped by whole widths *)
let[@inline] cell once n c =
  let fn = float_of_int n in
  if once then if c < 0. then 0 else if c >= fn then n - 1 else int_of_float c
  else begin
    let c = ref c in
    while !c < 0. do
      c := !c +. fn
    done;
    while !c >= fn do
      c := !c -. fn
    done;
    int_of_float !c
  end

let[@inline] texel b x y = Float.Array.unsafe_get b.heights ((cell b.once b.h y * b.w) + cell b.once b.w x)

(* The four corners' weights (POV-Ray's order: the pixel, left, up,
   up-left), bilinear (2) or by normalised inverse square distance (4) *)
let[@inline] weight interpolate p q k =
  if interpolate = 2 then
    if k = 0 then p *. q else if k = 1 then (1. -. p) *. q else if k = 2 then p *. (1. -. q) else (1. -. p) *. (1. -. q)
  else begin
    let p1 = 1. -. p and q1 = 1. -. q in
    let w0 = 1. /. ((p1 *. p1) +. (q1 *. q1)) and w1 = 1. /. ((p *. p) +. (q1 *. q1)) in
    let w2 = 1. /. ((p1 *. p1) +. (q *. q)) and w3 = 1. /. ((p *. p) +. (q *. q)) in
    let s = w0 +. w1 +. w2 +. w3 in
    (if k = 0 then w0 else if k = 1 then w1 else if k = 2 then w2 else w3) /. s
  end

(* the height at pixel coordinates: the pixel, or the four pixels around
   weighted *)
let[@inline] sample b x y =
  if b.interpolate = 0 then texel b x y
  else begin
    let x = x +. 0.5 and y = y +. 0.5 in
    let fx = float_of_int (int_of_float x) and fy = float_of_int (int_of_float y) in
    let p = x -. fx and q = y -. fy in
    let i = b.interpolate in
    0.
    +. (texel b fx fy *. weight i p q 0)
    +. (texel b (fx -. 1.) fy *. weight i p q 1)
    +. (texel b fx (fy -. 1.) *. weight i p q 2)
    +. (texel b (fx -. 1.) (fy -. 1.) *. weight i p q 3)
  end

(* POV-Ray's quirk with [use_index] on an image without a palette,
   interpolated: the corners' index -1 weighted and truncated stays -1
   only where the weights sum to 1 or more, else it is 0 *)
let[@inline] index_lost b x y =
  b.by_index && b.interpolate <> 0
  &&
  let x = x +. 0.5 and y = y +. 0.5 in
  let p = x -. float_of_int (int_of_float x) and q = y -. float_of_int (int_of_float y) in
  let i = b.interpolate in
  let t = 0. -. weight i p q 0 -. weight i p q 1 -. weight i p q 2 -. weight i p q 3 in
  t > -1.

(* one coordinate moved back into [0, n) by one width at most *)
let[@inline] wrap1 fn c = if c < 0. then c +. fn else if c >= fn then c -. fn else c

let eps = 1e-10
let two_pi = 2. *. Float.pi

(* The angle about y from +x towards +z, in [0, 2 pi), of a point at
   distance [len] > 0 from the y axis (POV-Ray's acos form: x along +x
   alone is 0, along -x pi) *)
let[@inline] around x z len =
  if z = 0. then if x > 0. then 0. else Float.pi
  else
    let a = Float.acos (x /. len) in
    if z < 0. then two_pi -. a else a

(* Where each map type puts a point on the image, before the common
   part of [locate]: u (columns) and v (rows from the bottom) into [c],
   in pixels, or false where POV-Ray finds no image (3.7,
   imageutil.cpp's planar, spherical, cylindrical and torus mappings,
   the planar one with image patterns' default gradient <1, -1, 0>: u
   from x, v from y). *)
let uv ~w ~h ~once ~map_type (q : Vec3.m) (c : Vec3.m) =
  let x = q.mx and y = q.my and z = q.mz in
  let fw = float_of_int w and fh = float_of_int h in
  match map_type with
  | 1 ->
      (* the unit sphere: the longitude, the latitude from the south pole *)
      let len = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      len > 0.
      &&
      let x = x /. len and y = y /. len and z = z /. len in
      (* (a point rounded just past a pole: asin is given 1) *)
      let phi = 0.5 +. (Float.asin (Float.min 1. (Float.max (-1.) y)) /. Float.pi) in
      let l = Float.sqrt ((x *. x) +. (z *. z)) in
      let theta = if l = 0. then 0. else around x z l /. two_pi in
      Vec3.set c (theta *. fw) (phi *. fh) 0.;
      true
  | 2 ->
      (* the cylinder about y: the longitude, the height y from 0 to 1 *)
      (not (once && (y < 0. || y > 1.)))
      &&
      let len = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      len > 0.
      &&
      let x = x /. len and z = z /. len in
      let l = Float.sqrt ((x *. x) +. (z *. z)) in
      l > 0.
      &&
      (Vec3.set c (around x z l /. two_pi *. fw) (Float.rem (y *. fh) fh) 0.;
       true)
  | 5 ->
      (* the torus of major radius 1 about y: the angle about y, the angle
         about the tube from its inside, turning through -y *)
      let len = Float.sqrt ((x *. x) +. (z *. z)) in
      len > 0.
      &&
      let theta = around x z len in
      let r = len -. 1. in
      let tube = Float.sqrt ((r *. r) +. (y *. y)) in
      tube > 0.
      &&
      let phi = Float.acos (Float.min 1. (Float.max (-1.) (-.r /. tube))) in
      let phi = if y > 0. then two_pi -. phi else phi in
      Vec3.set c (theta /. two_pi *. fw) (phi /. two_pi *. fh) 0.;
      true
  | _ ->
      (* planar, as POV-Ray maps every other number *)
      (not (once && (x < 0. || x > 1. || y < 0. || y > 1.)))
      &&
      (Vec3.set c (Float.rem (x *. fw) fw) (Float.rem (y *. fh) fh) 0.;
       true)

(* the image coordinates of a point, per domain *)
let coords_key = Scratch.key Vec3.m

(* POV-Ray's map_pos (3.7.0, imageutil.cpp): the pixel coordinates of
   the point (pattern space) into [c] (c.mx the column, c.my the row
   from the top, in [0, w) and [0, h)), or false off the image: a tiny
   offset added, once-only images refused past their edges, whole
   images taken off, rows counted from the top. A point whose
   coordinates are not finite is off the image. *)
let locate ~w ~h ~once ~map_type (q : Vec3.m) (c : Vec3.m) =
  uv ~w ~h ~once ~map_type q c
  &&
  let fw = float_of_int w and fh = float_of_int h in
  let xc = c.mx +. eps and yc = c.my +. eps in
  let xx = xc /. fw and yy = yc /. fh in
  xc -. xc = 0. && yc -. yc = 0.
  && (not (once && (xx > 1. || yy > 1. || xx < 0. || yy < 0.)))
  &&
  let xc = xc -. (float_of_int (int_of_float xx) *. fw) and yc = yc -. (float_of_int (int_of_float yy) *. fh) in
  (* image rows run down *)
  Vec3.set c (wrap1 fw xc) (wrap1 fh (fh -. yc)) 0.;
  true

let tilt b amount (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let c = Scratch.get coords_key in
  if not (locate ~w:b.w ~h:b.h ~once:b.once ~map_type:b.map_type q c) then Vec3.set out n.mx n.my n.mz
  else begin
    let fw = float_of_int b.w and fh = float_of_int b.h in
    let xc = c.mx and yc = c.my in
    let h1 = sample b xc yc and lost1 = index_lost b xc yc in
    let xc2 = wrap1 fw (xc -. 1.) and yc = wrap1 fh (yc +. 1.) in
    let h2 = sample b xc2 yc and lost2 = index_lost b xc2 yc in
    let xc = wrap1 fw (xc2 +. 2.) in
    let h3 = sample b xc yc and lost3 = index_lost b xc yc in
    (* all three read as index 0: no relief *)
    let flat = lost1 && lost2 && lost3 in
    let h1 = if flat then 0. else h1 and h2 = if flat then 0. else h2 and h3 = if flat then 0. else h3 in
    (* the triangle's normal: (p3 - p2) x (p1 - p2) *)
    let ay = (amount *. h3) -. (amount *. h2) and by = (amount *. h1) -. (amount *. h2) in
    let bx = (ay *. -1.) -. (0. *. by) and bym = (0. *. 1.) -. (2. *. -1.) and bz = (2. *. by) -. (ay *. 1.) in
    let l = Float.sqrt ((bx *. bx) +. (bym *. bym) +. (bz *. bz)) in
    let bx = bx /. l and bym = bym /. l and bz = bz /. l in
    (* the frame: y along the normal, x along n x (0, 1, 0) *)
    let xpx = -.n.mz and xpz = n.mx in
    let len = Float.sqrt ((xpx *. xpx) +. (xpz *. xpz)) in
    (* a normal along y: the frame of y itself (or of -y) *)
    let flat = len < eps in
    let yx = if flat then 0. else n.mx and yz = if flat then 0. else n.mz in
    let yy = if not flat then n.my else if Float.abs (n.my -. 1.) < eps then 1. else -1. in
    let xpx = if flat then 1. else xpx and xpz = if flat then 0. else xpz in
    let len = if flat then 1. else len in
    let xpx = xpx /. len and xpz = xpz /. len in
    (* z = x cross y, unit *)
    let zx = (0. *. yz) -. (xpz *. yy) and zy = (xpz *. yx) -. (xpx *. yz) and zz = (xpx *. yy) -. (0. *. yx) in
    let zl = Float.sqrt ((zx *. zx) +. (zy *. zy) +. (zz *. zz)) in
    let zx = zx /. zl and zy = zy /. zl and zz = zz /. zl in
    Vec3.set out
      ((xpx *. bx) +. (yx *. bym) +. -.(zx *. bz))
      ((0. *. bx) +. (yy *. bym) +. -.(zy *. bz))
      ((xpz *. bx) +. (yz *. bym) +. -.(zz *. bz))
  end

let pixel ~w ~h ~once q =
  let c = Scratch.get coords_key in
  if not (locate ~w ~h ~once ~map_type:0 q c) then -1 else (cell once h c.my * w) + cell once w c.mx

let[@inline] value b q =
  let c = Scratch.get coords_key in
  if not (locate ~w:b.w ~h:b.h ~once:b.once ~map_type:b.map_type q c) then 0.
  else
    let v = sample b c.mx c.my in
    if v < 0. then 0. else if v > 1. then 1. else v
