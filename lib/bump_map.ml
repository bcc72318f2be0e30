type t = { w : int; h : int; once : bool; interpolate : int; by_index : bool; heights : Float.Array.t }

let make ~w ~h ~once ~interpolate ~by_index heights =
  if w <= 0 || h <= 0 || Float.Array.length heights <> w * h then invalid_arg "Bump_map.make: size";
  if interpolate <> 0 && interpolate <> 2 && interpolate <> 4 then invalid_arg "Bump_map.make: interpolate";
  { w; h; once; interpolate; by_index; heights }

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

let tilt b amount (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let x = q.mx and y = q.my in
  let fw = float_of_int b.w and fh = float_of_int b.h in
  let xc = Float.rem (x *. fw) fw +. eps and yc = Float.rem (y *. fh) fh +. eps in
  let xx = xc /. fw and yy = yc /. fh in
  if (b.once && (x < 0. || x > 1. || y < 0. || y > 1.)) || (b.once && (xx > 1. || yy > 1. || xx < 0. || yy < 0.))
  then Vec3.set out n.mx n.my n.mz
  else begin
    let xc = xc -. (float_of_int (int_of_float xx) *. fw) and yc = yc -. (float_of_int (int_of_float yy) *. fh) in
    (* image rows run down *)
    let yc = fh -. yc in
    let xc = wrap1 fw xc and yc = wrap1 fh yc in
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

let pixel ~w ~h ~once x y =
  let fw = float_of_int w and fh = float_of_int h in
  let xc = Float.rem (x *. fw) fw +. eps and yc = Float.rem (y *. fh) fh +. eps in
  let xx = xc /. fw and yy = yc /. fh in
  if (once && (x < 0. || x > 1. || y < 0. || y > 1.)) || (once && (xx > 1. || yy > 1. || xx < 0. || yy < 0.)) then -1
  else begin
    let xc = xc -. (float_of_int (int_of_float xx) *. fw) and yc = yc -. (float_of_int (int_of_float yy) *. fh) in
    let yc = wrap1 fh (fh -. yc) and xc = wrap1 fw xc in
    (cell once h yc * w) + cell once w xc
  end
