(* POV-Ray's height_field (see height_field.mli). Everything is worked out
   in the grid's own units, as hfield.cpp does: x in 0 .. w-1, z in
   0 .. d-1, y in raw 16-bit units; object space is that scaled by
   1/(w-1), 1/65536, 1/(d-1). A ray is scaled into grid units (its
   distances do not change) and walks the cells it crosses inside the
   field's box, nearest first; the first cell with a crossing holds the
   nearest one. *)

type t = {
  nx : int;  (** grid points along x *)
  nz : int;  (** along z *)
  hgt : Float.Array.t;  (** raw heights, [z * nx + x], z = 0 the image's bottom row *)
  ylo : float;  (** the box, raw units: max (lowest, water) - 0.001 *)
  yhi : float;  (** highest + 0.001 *)
  sx : float;  (** nx - 1 *)
  sz : float;  (** nz - 1 *)
  nrm : Float.Array.t;  (** smooth: 3 a grid point, POV-Ray's 16-bit integers; else empty *)
  wn : Float.Array.t;  (** 9: grid normal to world normal (row major) *)
  wt : Float.Array.t;  (** 9: world normal back to object space (transpose of the transform) *)
}

let hf_offset = 0.001
let epsilon = 1e-10
let width f = f.nx
let depth f = f.nz
let smooth f = Float.Array.length f.nrm > 0
let[@inline] hg f x z = Float.Array.unsafe_get f.hgt ((z * f.nx) + x)
let height f i j = Float.Array.get f.hgt ((j * f.nx) + i)

(* hfield.cpp's smooth_height_field: at each grid point the normalised
   sum of the unit normals of the (up to) four fan triangles, stored as
   (short)(32767 n) *)
let smooth_normals nx nz hgt =
  let xs = nx - 1 and zs = nz - 1 in
  let h x z = Float.Array.get hgt ((z * nx) + x) in
  let out = Float.Array.make (3 * nx * nz) 0. in
  for i = 0 to zs do
    for j = 0 to xs do
      let sx = ref 0. and sy = ref 0. and sz = ref 0. in
      let add x0 z0 x1 z1 x2 z2 =
        if x0 >= 0 && z0 >= 0 && x1 >= 0 && z1 >= 0 && x2 >= 0 && z2 >= 0 && x0 <= xs && z0 <= zs && x1 <= xs
           && z1 <= zs && x2 <= xs && z2 <= zs
        then begin
          let v0 = Vec3.make (float x0) (h x0 z0) (float z0) in
          let v1 = Vec3.make (float x1) (h x1 z1) (float z1) in
          let v2 = Vec3.make (float x2) (h x2 z2) (float z2) in
          let n = Vec3.normalize (Vec3.cross (Vec3.sub v2 v0) (Vec3.sub v1 v0)) in
          let n = if n.y < 0. then Vec3.neg n else n in
          sx := !sx +. n.x;
          sy := !sy +. n.y;
          sz := !sz +. n.z
        end
      in
      add j i (j + 1) i j (i + 1);
      add j i j (i + 1) (j - 1) i;
      add j i (j - 1) i j (i - 1);
      add j i j (i - 1) (j + 1) i;
      let n = Vec3.normalize (Vec3.make !sx !sy !sz) in
      let k = 3 * ((i * nx) + j) in
      (* C's (short) conversion truncates toward zero *)
      Float.Array.set out k (Float.trunc (32767. *. n.x));
      Float.Array.set out (k + 1) (Float.trunc (32767. *. n.y));
      Float.Array.set out (k + 2) (Float.trunc (32767. *. n.z))
    done
  done;
  out

let matrices sx sz xf =
  let col v = Transform.normal xf v in
  (* world normal of a grid normal: M^-T S^T, columns the images of the axes *)
  let c0 = col (Vec3.make sx 0. 0.) and c1 = col (Vec3.make 0. 65536. 0.) and c2 = col (Vec3.make 0. 0. sz) in
  let wn = Float.Array.of_list [ c0.x; c1.x; c2.x; c0.y; c1.y; c2.y; c0.z; c1.z; c2.z ] in
  let back v =
    let m = Vec3.m () in
    Vec3.load m v;
    Transform.normal_inverse_m xf m;
    Vec3.of_m m
  in
  let d0 = back Vec3.unit_x and d1 = back Vec3.unit_y and d2 = back Vec3.unit_z in
  let wt = Float.Array.of_list [ d0.x; d1.x; d2.x; d0.y; d1.y; d2.y; d0.z; d1.z; d2.z ] in
  (wn, wt)

let make ~width ~depth ~heights ~smooth ~water =
  if width < 2 || depth < 2 then invalid_arg "Height_field.make: fewer than 2 x 2 points";
  if Array.length heights <> width * depth then invalid_arg "Height_field.make: wrong number of heights";
  let nx = width and nz = depth in
  let hgt = Float.Array.make (nx * nz) 0. in
  (* Compute_HField: map row z is the image's row depth - 1 - z *)
  for z = 0 to nz - 1 do
    for x = 0 to nx - 1 do
      Float.Array.set hgt ((z * nx) + x) (float heights.(((nz - 1 - z) * nx) + x))
    done
  done;
  let lo = Float.Array.fold_left Float.min infinity hgt and hi = Float.Array.fold_left Float.max neg_infinity hgt in
  let water = 65536. *. water in
  let sx = float (nx - 1) and sz = float (nz - 1) in
  let wn, wt = matrices sx sz Transform.identity in
  {
    nx; nz; hgt; sx; sz; wn; wt;
    ylo = Float.max lo water -. hf_offset;
    yhi = hi +. hf_offset;
    nrm = (if smooth then smooth_normals nx nz hgt else Float.Array.make 0 0.);
  }

let place f xf =
  let wn, wt = matrices f.sx f.sz xf in
  { f with wn; wt }

let bounds f = (Vec3.make 0. (f.ylo /. 65536.) 0., Vec3.make 1. (f.yhi /. 65536.) 1.)

(* intersect_pixel's two triangles of cell (x, z), accepting distances in
   [lo, h.t) (lo already above tmin and the box's entry) and up to [hi]
   (the box's exit); the nearer recorded in [h] *)
let[@inline] cell f x z ox oy oz dx dy dz lo hi (h : Hit.t) =
  let y1 = hg f x z and y2 = hg f (x + 1) z and y3 = hg f x (z + 1) and y4 = hg f (x + 1) (z + 1) in
  let fx = float x and fz = float z in
  (* first triangle: (x, z), (x+1, z), (x, z+1) *)
  let nx = y1 -. y2 and nz = y1 -. y3 in
  let d1 = (nx *. dx) +. dy +. (nz *. dz) in
  if d1 > epsilon || d1 < -.epsilon then begin
    let t = ((nx *. (fx -. ox)) +. (y1 -. oy) +. (nz *. (fz -. oz))) /. d1 in
    if t >= lo && t <= hi && t < h.t then begin
      let s = ox +. (t *. dx) -. fx and u = oz +. (t *. dz) -. fz in
      if s >= -0.0001 && u >= -0.0001 && s +. u <= 1.0001 then begin
        h.t <- t;
        h.id <- float (2 * ((z * f.nx) + x))
      end
    end
  end;
  (* second: (x+1, z+1), (x, z+1), (x+1, z) *)
  let nx = y3 -. y4 and nz = y2 -. y4 in
  let d2 = (nx *. dx) +. dy +. (nz *. dz) in
  if d2 > epsilon || d2 < -.epsilon then begin
    let t = ((nx *. (fx +. 1. -. ox)) +. (y4 -. oy) +. (nz *. (fz +. 1. -. oz))) /. d2 in
    if t >= lo && t <= hi && t < h.t then begin
      let s = ox +. (t *. dx) -. fx and u = oz +. (t *. dz) -. fz in
      if s <= 1.0001 && u <= 1.0001 && s +. u >= 0.9999 then begin
        h.t <- t;
        h.id <- float ((2 * ((z * f.nx) + x)) + 1)
      end
    end
  end

let hit_s f (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] unboxes [tmin]: a branch choosing between it (boxed, an
     argument) and an unboxed float would box the result *)
  let tmin = tmin +. 0. in
  let sx = f.sx and sz = f.sz in
  let ox = r.ox *. sx and oy = r.oy *. 65536. and oz = r.oz *. sz in
  let dx = r.dx *. sx and dy = r.dy *. 65536. and dz = r.dz *. sz in
  (* the box [0, sx] x [ylo, yhi] x [0, sz] *)
  let t0 = ref neg_infinity and t1 = ref infinity and miss = ref false in
  if dx = 0. then (if ox < 0. || ox > sx then miss := true)
  else begin
    let a = -.ox /. dx and b = (sx -. ox) /. dx in
    t0 := Float.max !t0 (Float.min a b);
    t1 := Float.min !t1 (Float.max a b)
  end;
  if dy = 0. then (if oy < f.ylo || oy > f.yhi then miss := true)
  else begin
    let a = (f.ylo -. oy) /. dy and b = (f.yhi -. oy) /. dy in
    t0 := Float.max !t0 (Float.min a b);
    t1 := Float.min !t1 (Float.max a b)
  end;
  if dz = 0. then (if oz < 0. || oz > sz then miss := true)
  else begin
    let a = -.oz /. dz and b = (sz -. oz) /. dz in
    t0 := Float.max !t0 (Float.min a b);
    t1 := Float.min !t1 (Float.max a b)
  end;
  let lo = Float.max !t0 (Float.max tmin h.floor) in
  (* strictly beyond tmin and the floor *)
  let lo = if lo <= tmin || lo <= h.floor then Float.succ lo else lo in
  let hi = !t1 in
  let te = Float.min hi h.t in
  if !miss || lo > te then false
  else begin
    let t_in = h.t in
    let ncx = f.nx - 2 and ncz = f.nz - 2 in
    let px = ox +. (lo *. dx) and pz = oz +. (lo *. dz) in
    let cx = ref (Int.max 0 (Int.min ncx (int_of_float (Float.floor px)))) in
    let cz = ref (Int.max 0 (Int.min ncz (int_of_float (Float.floor pz)))) in
    let stepx = if dx > 0. then 1 else -1 and stepz = if dz > 0. then 1 else -1 in
    let tdx = if dx = 0. then infinity else Float.abs (1. /. dx) in
    let tdz = if dz = 0. then infinity else Float.abs (1. /. dz) in
    let tmx =
      ref (if dx > 0. then (float (!cx + 1) -. ox) /. dx else if dx < 0. then (float !cx -. ox) /. dx else infinity)
    in
    let tmz =
      ref (if dz > 0. then (float (!cz + 1) -. oz) /. dz else if dz < 0. then (float !cz -. oz) /. dz else infinity)
    in
    let tc = ref lo and go = ref true in
    while !go do
      (* by one comparison each (Floats.fmin): no NaN here, and a zero's
         sign is read only by comparisons *)
      let tn = Floats.fmin te (Floats.fmin !tmx !tmz) in
      let ya = oy +. (!tc *. dy) and yb = oy +. (tn *. dy) in
      let ymin = Floats.fmin ya yb -. 1e-3 and ymax = Floats.fmax ya yb +. 1e-3 in
      let x = !cx and z = !cz in
      let y1 = hg f x z and y2 = hg f (x + 1) z and y3 = hg f x (z + 1) and y4 = hg f (x + 1) (z + 1) in
      let cmin = Floats.fmin (Floats.fmin y1 y2) (Floats.fmin y3 y4)
      and cmax = Floats.fmax (Floats.fmax y1 y2) (Floats.fmax y3 y4) in
      if cmax >= ymin && cmin <= ymax then cell f x z ox oy oz dx dy dz lo hi h;
      if h.t < t_in || tn >= te then go := false
      else if !tmx < !tmz then begin
        cx := !cx + stepx;
        tc := !tmx;
        tmx := !tmx +. tdx;
        if !cx < 0 || !cx > ncx then go := false
      end
      else begin
        cz := !cz + stepz;
        tc := !tmz;
        tmz := !tmz +. tdz;
        if !cz < 0 || !cz > ncz then go := false
      end
    done;
    h.t < t_in
  end

let normal_into f (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  if Float.Array.length f.nrm = 0 then begin
    let id = int_of_float h.id in
    let c = id / 2 in
    let x = c mod f.nx and z = c / f.nx in
    let nx, nz =
      if id land 1 = 0 then
        let y1 = hg f x z in
        (y1 -. hg f (x + 1) z, y1 -. hg f x (z + 1))
      else
        let y4 = hg f (x + 1) (z + 1) in
        (hg f x (z + 1) -. y4, hg f (x + 1) z -. y4)
    in
    (* grid normal to object space: S^T *)
    let ax = nx *. f.sx and ay = 65536. and az = nz *. f.sz in
    let l = Float.sqrt ((ax *. ax) +. (ay *. ay) +. (az *. az)) in
    Vec3.set out (ax /. l) (ay /. l) (az /. l)
  end
  else begin
    (* HField::Normal: the cell of the point, the four corner normals each
       taken to world space and normalised, blended bilinearly *)
    let gx = p.mx *. f.sx and gz = p.mz *. f.sz in
    let px = Int.min (truncate gx) (f.nx - 2) and pz = Int.min (truncate gz) (f.nz - 2) in
    let px = Int.max px 0 and pz = Int.max pz 0 in
    let x = gx -. float px and z = gz -. float pz in
    let u = 1. -. x and v = 1. -. z in
    let wn = f.wn and nrm = f.nrm in
    let rx = ref 0. and ry = ref 0. and rz = ref 0. in
    for k = 0 to 3 do
      let i = px + (k land 1) and j = pz + (k lsr 1) in
      let b = 3 * ((j * f.nx) + i) in
      let a0 = Float.Array.unsafe_get nrm b and a1 = Float.Array.unsafe_get nrm (b + 1)
      and a2 = Float.Array.unsafe_get nrm (b + 2) in
      let w0 = (Float.Array.unsafe_get wn 0 *. a0) +. (Float.Array.unsafe_get wn 1 *. a1) +. (Float.Array.unsafe_get wn 2 *. a2) in
      let w1 = (Float.Array.unsafe_get wn 3 *. a0) +. (Float.Array.unsafe_get wn 4 *. a1) +. (Float.Array.unsafe_get wn 5 *. a2) in
      let w2 = (Float.Array.unsafe_get wn 6 *. a0) +. (Float.Array.unsafe_get wn 7 *. a1) +. (Float.Array.unsafe_get wn 8 *. a2) in
      let l = Float.sqrt ((w0 *. w0) +. (w1 *. w1) +. (w2 *. w2)) in
      let wgt = (if k lsr 1 = 0 then v else z) *. if k land 1 = 0 then u else x in
      let c = if l > 0. then wgt /. l else 0. in
      rx := !rx +. (c *. w0);
      ry := !ry +. (c *. w1);
      rz := !rz +. (c *. w2)
    done;
    let wt = f.wt in
    let o0 = (Float.Array.unsafe_get wt 0 *. !rx) +. (Float.Array.unsafe_get wt 1 *. !ry) +. (Float.Array.unsafe_get wt 2 *. !rz) in
    let o1 = (Float.Array.unsafe_get wt 3 *. !rx) +. (Float.Array.unsafe_get wt 4 *. !ry) +. (Float.Array.unsafe_get wt 5 *. !rz) in
    let o2 = (Float.Array.unsafe_get wt 6 *. !rx) +. (Float.Array.unsafe_get wt 7 *. !ry) +. (Float.Array.unsafe_get wt 8 *. !rz) in
    let l = Float.sqrt ((o0 *. o0) +. (o1 *. o1) +. (o2 *. o2)) in
    if l > 0. then Vec3.set out (o0 /. l) (o1 /. l) (o2 /. l) else Vec3.set out 0. 1. 0.
  end

(* HField::Inside, in grid units *)
let inside f x y z =
  let tx = x *. f.sx and ty = y *. 65536. and tz = z *. f.sz in
  if tx < 0. || tx >= f.sx || tz < 0. || tz >= f.sz then false
  else if ty >= f.yhi then false
  else if ty < f.ylo then true
  else
    (* POV-Ray's water here is the box's floor *)
    let w = f.ylo in
    let px = truncate tx and pz = truncate tz in
    let fx = tx -. float px and fz = tz -. float pz in
    if fx +. fz < 1. then
      let y1 = Float.max (hg f px pz) w and y2 = Float.max (hg f (px + 1) pz) w and y3 = Float.max (hg f px (pz + 1)) w in
      (* below the plane through the corner with normal (y1-y2, 1, y1-y3) *)
      ((y1 -. y2) *. (tx -. float px)) +. (ty -. y1) +. ((y1 -. y3) *. (tz -. float pz)) < 0.
    else
      let px = int_of_float (Float.ceil tx) and pz = int_of_float (Float.ceil tz) in
      let y1 = Float.max (hg f px pz) w and y2 = Float.max (hg f (px - 1) pz) w and y3 = Float.max (hg f px (pz - 1)) w in
      ((y2 -. y1) *. (tx -. float px)) +. (ty -. y1) +. ((y3 -. y1) *. (tz -. float pz)) < 0.

(* the triangles' height at (x, z), object units *)
let surface f x z =
  let tx = x *. f.sx and tz = z *. f.sz in
  let px = Int.max 0 (Int.min (f.nx - 2) (truncate tx)) and pz = Int.max 0 (Int.min (f.nz - 2) (truncate tz)) in
  let s = tx -. float px and u = tz -. float pz in
  let y =
    if s +. u <= 1. then
      let y1 = hg f px pz in
      y1 +. (s *. (hg f (px + 1) pz -. y1)) +. (u *. (hg f px (pz + 1) -. y1))
    else
      let y4 = hg f (px + 1) (pz + 1) in
      y4 +. ((1. -. s) *. (hg f px (pz + 1) -. y4)) +. ((1. -. u) *. (hg f (px + 1) pz -. y4))
  in
  y /. 65536.
