(* A 3x4 matrix acting on column vectors, p' = M p + t, kept with its
   inverse. Entries are row-major: m.(0..2) is the first row, m.(9..11) the
   translation. *)
(* [plain]: made by [translate] and [scale] alone, which POV-Ray applies
   to some shapes' own numbers rather than keeping a transformation;
   [turn]: made by one [rotate] (a plane turns its normal) *)
type t = { m : Float.Array.t; inv : Float.Array.t; id : bool; plain : bool; turn : bool }

let mk a = Float.Array.of_list (Array.to_list a)

let identity_m = mk [| 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |]
let identity = { m = identity_m; inv = identity_m; id = true; plain = true; turn = false }
let is_identity t = t.id
let g = Float.Array.get

(* product of two 3x4 affine matrices: (a then b) = B * A. The sums run
   in POV-Ray's order (matrices.cpp's MTimesA and MTimesB): the products
   first, b's translation added last, so a composed transformation
   rounds as POV-Ray's does (a face on a pattern's cell boundary falls
   on the same side) *)
let mul b a =
  let r = Float.Array.make 12 0. in
  for i = 0 to 2 do
    for j = 0 to 2 do
      let s = ref 0. in
      for k = 0 to 2 do
        s := !s +. (g b ((3 * i) + k) *. g a ((3 * k) + j))
      done;
      Float.Array.set r ((3 * i) + j) !s
    done;
    let s = ref 0. in
    for k = 0 to 2 do
      s := !s +. (g b ((3 * i) + k) *. g a (9 + k))
    done;
    Float.Array.set r (9 + i) (!s +. g b (9 + i))
  done;
  r

let det3 m =
  (g m 0 *. ((g m 4 *. g m 8) -. (g m 5 *. g m 7)))
  -. (g m 1 *. ((g m 3 *. g m 8) -. (g m 5 *. g m 6)))
  +. (g m 2 *. ((g m 3 *. g m 7) -. (g m 4 *. g m 6)))

let invert m =
  let d = det3 m in
  if d = 0. || not (Float.is_finite d) then None
  else
    let id = 1. /. d in
    let c i j = g m ((3 * i) + j) in
    let r = Float.Array.make 12 0. in
    let set i j v = Float.Array.set r ((3 * i) + j) (v *. id) in
    set 0 0 ((c 1 1 *. c 2 2) -. (c 1 2 *. c 2 1));
    set 0 1 ((c 0 2 *. c 2 1) -. (c 0 1 *. c 2 2));
    set 0 2 ((c 0 1 *. c 1 2) -. (c 0 2 *. c 1 1));
    set 1 0 ((c 1 2 *. c 2 0) -. (c 1 0 *. c 2 2));
    set 1 1 ((c 0 0 *. c 2 2) -. (c 0 2 *. c 2 0));
    set 1 2 ((c 0 2 *. c 1 0) -. (c 0 0 *. c 1 2));
    set 2 0 ((c 1 0 *. c 2 1) -. (c 1 1 *. c 2 0));
    set 2 1 ((c 0 1 *. c 2 0) -. (c 0 0 *. c 2 1));
    set 2 2 ((c 0 0 *. c 1 1) -. (c 0 1 *. c 1 0));
    for i = 0 to 2 do
      let s = ref 0. in
      for k = 0 to 2 do
        s := !s +. (g r ((3 * i) + k) *. g m (9 + k))
      done;
      Float.Array.set r (9 + i) (-. !s)
    done;
    Some r

let of_pair m inv = { m; inv; id = false; plain = false; turn = false }

let plain t = { t with plain = true }
let opaque t = if t.id then t else { t with plain = false; turn = false }

let translate (v : Vec3.t) =
  plain @@ of_pair
    (mk [| 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0.; 1.; v.x; v.y; v.z |])
    (mk [| 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0.; 1.; -.v.x; -.v.y; -.v.z |])

let scale (v : Vec3.t) =
  plain @@ of_pair
    (mk [| v.x; 0.; 0.; 0.; v.y; 0.; 0.; 0.; v.z; 0.; 0.; 0. |])
    (mk [| 1. /. v.x; 0.; 0.; 0.; 1. /. v.y; 0.; 0.; 0.; 1. /. v.z; 0.; 0.; 0. |])

let transpose3 m =
  let c i j = g m ((3 * j) + i) in
  mk [| c 0 0; c 0 1; c 0 2; c 1 0; c 1 1; c 1 2; c 2 0; c 2 1; c 2 2; 0.; 0.; 0. |]

(* A pure rotation: the inverse is the transpose. *)
let of_rotation m = of_pair m (transpose3 m)

(* degrees times pi/180, as POV-Ray scales a rotation's vector by
   M_PI_180 (a *. Float.pi /. 180. rounds differently for 384 of the
   whole angles from -720 to 720) *)
let deg a = a *. (Float.pi /. 180.)

let rot_x a =
  let c = Float.cos (deg a) and s = Float.sin (deg a) in
  of_rotation (mk [| 1.; 0.; 0.; 0.; c; -.s; 0.; s; c; 0.; 0.; 0. |])

let rot_y a =
  let c = Float.cos (deg a) and s = Float.sin (deg a) in
  of_rotation (mk [| c; 0.; s; 0.; 1.; 0.; -.s; 0.; c; 0.; 0.; 0. |])

let rot_z a =
  let c = Float.cos (deg a) and s = Float.sin (deg a) in
  of_rotation (mk [| c; -.s; 0.; s; c; 0.; 0.; 0.; 1.; 0.; 0.; 0. |])

let then_ a b =
  if a.id then b
  else if b.id then a
  else { m = mul b.m a.m; inv = mul a.inv b.inv; id = false; plain = a.plain && b.plain; turn = false }

let rotate (v : Vec3.t) =
  let r = then_ (then_ (rot_x v.x) (rot_y v.y)) (rot_z v.z) in
  { r with turn = true }

(* POV-Ray's rotation by [angle] degrees about [axis] (matrices.cpp's
   Compute_Axis_Rotation_Transform, its sums in its order; the inverse
   is the transpose) *)
let axis_rotate axis angle =
  let a = Vec3.normalize axis in
  let c = Float.cos (deg angle) and s = Float.sin (deg angle) in
  let x = a.x and y = a.y and z = a.z in
  of_rotation
    (mk
       [|
         (x *. x) +. (c *. (1. -. (x *. x))); (x *. y *. (1. -. c)) -. (z *. s); (x *. z *. (1. -. c)) +. (y *. s);
         (x *. y *. (1. -. c)) +. (z *. s); (y *. y) +. (c *. (1. -. (y *. y))); (y *. z *. (1. -. c)) -. (x *. s);
         (x *. z *. (1. -. c)) -. (y *. s); (y *. z *. (1. -. c)) +. (x *. s); (z *. z) +. (c *. (1. -. (z *. z)));
         0.; 0.; 0.;
       |])

let of_pov_matrix a =
  if Array.length a <> 12 then invalid_arg "Transform.of_pov_matrix";
  (* POV-Ray's rows are the images of x, y, z: transpose into columns. *)
  let m =
    mk [| a.(0); a.(3); a.(6); a.(1); a.(4); a.(7); a.(2); a.(5); a.(8); a.(9); a.(10); a.(11) |]
  in
  Option.map (fun inv -> of_pair m inv) (invert m)

let inverse t = { t with m = t.inv; inv = t.m }

(* no rotation or shear: zero off the diagonal *)
let diagonal m = g m 1 = 0. && g m 2 = 0. && g m 3 = 0. && g m 5 = 0. && g m 6 = 0. && g m 7 = 0.

let as_translation t =
  let m = t.m in
  if t.plain && (not t.id) && diagonal m && g m 0 = 1. && g m 4 = 1. && g m 8 = 1. then
    Some (Vec3.make (g m 9) (g m 10) (g m 11))
  else None

let as_scale t =
  let m = t.m in
  if t.plain && (not t.id) && diagonal m && g m 9 = 0. && g m 10 = 0. && g m 11 = 0. then
    Some (Vec3.make (g m 0) (g m 4) (g m 8))
  else None

let is_turn t = t.turn

let[@inline] app m (p : Vec3.t) o =
  Vec3.make
    ((g m 0 *. p.x) +. (g m 1 *. p.y) +. (g m 2 *. p.z) +. (o *. g m 9))
    ((g m 3 *. p.x) +. (g m 4 *. p.y) +. (g m 5 *. p.z) +. (o *. g m 10))
    ((g m 6 *. p.x) +. (g m 7 *. p.y) +. (g m 8 *. p.z) +. (o *. g m 11))

let point t p = if t.id then p else app t.m p 1.
let vector t v = if t.id then v else app t.m v 0.
let inv_point t p = if t.id then p else app t.inv p 1.
let inv_vector t v = if t.id then v else app t.inv v 0.

let normal t (n : Vec3.t) =
  if t.id then n
  else
    let m = t.inv in
    Vec3.make
      ((g m 0 *. n.x) +. (g m 3 *. n.y) +. (g m 6 *. n.z))
      ((g m 1 *. n.x) +. (g m 4 *. n.y) +. (g m 7 *. n.z))
      ((g m 2 *. n.x) +. (g m 5 *. n.y) +. (g m 8 *. n.z))

(* the affine map of the 3x4 row-major [m] (translation last) applied
   to the point [p], into [out] ([p] and [out] may be the same vector) *)
let[@inline] affine_m m (p : Vec3.m) (out : Vec3.m) =
  let x = p.mx and y = p.my and z = p.mz in
  Vec3.set out
    ((g m 0 *. x) +. (g m 1 *. y) +. (g m 2 *. z) +. (1. *. g m 9))
    ((g m 3 *. x) +. (g m 4 *. y) +. (g m 5 *. z) +. (1. *. g m 10))
    ((g m 6 *. x) +. (g m 7 *. y) +. (g m 8 *. z) +. (1. *. g m 11))

(* [inv_point] and [point] in place, the same arithmetic *)
let inv_point_m t (p : Vec3.m) (out : Vec3.m) =
  if t.id then Vec3.set out p.mx p.my p.mz else affine_m t.inv p out

let point_m t (p : Vec3.m) (out : Vec3.m) = if t.id then Vec3.set out p.mx p.my p.mz else affine_m t.m p out

let[@inline] transpose_m m (n : Vec3.m) =
  let x = n.mx and y = n.my and z = n.mz in
  Vec3.set n
    ((g m 0 *. x) +. (g m 3 *. y) +. (g m 6 *. z))
    ((g m 1 *. x) +. (g m 4 *. y) +. (g m 7 *. z))
    ((g m 2 *. x) +. (g m 5 *. y) +. (g m 8 *. z))

let normal_m t n = if not t.id then transpose_m t.inv n

(* [normal (inverse t)] in place *)
let normal_inverse_m t n = if not t.id then transpose_m t.m n

let determinant t = det3 t.m

let to_string t =
  String.concat " "
    (List.init 12 (fun i -> Printf.sprintf "%g" (g t.m i)))
