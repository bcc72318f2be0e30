(* Generators shared by the geometry tests: random shapes, transforms,
   rays, and the implicit surface equations the hits must satisfy. *)
open Camlray

let v = Vec3.make
let fr lo hi = QCheck.Gen.float_range lo hi
let gvec r = QCheck.Gen.(map3 Vec3.make (fr (-.r) r) (fr (-.r) r) (fr (-.r) r))

let gdir =
  QCheck.Gen.(
    map (fun d -> if Vec3.length d < 1e-3 then Vec3.unit_z else Vec3.normalize d) (gvec 1.))

(* A non-degenerate shape around the origin (within ~2 units). *)
let gshape =
  let open QCheck.Gen in
  oneof
    [
      map2 Shape.sphere (gvec 0.5) (fr 0.3 1.5);
      map2 (fun c e -> Shape.box (Vec3.sub c e) (Vec3.add c e)) (gvec 0.5)
        (map3 Vec3.make (fr 0.2 1.) (fr 0.2 1.) (fr 0.2 1.));
      map3 (fun a d (r, o) -> Shape.cylinder ~open_:o a (Vec3.madd a 1.5 d) r) (gvec 0.5) gdir
        (pair (fr 0.2 1.) bool);
      map3 (fun a d (r0, r1, o) -> Shape.cone ~open_:o a r0 (Vec3.madd a 1.5 d) r1) (gvec 0.5) gdir
        (triple (fr 0. 1.) (fr 0.1 1.) bool);
      map2 Shape.torus (fr 0.5 1.5) (fr 0.1 0.5);
      map3 (fun c n (r, h) -> Shape.disc ~hole:(h *. r) c n r) (gvec 0.5) gdir (pair (fr 0.3 1.5) (fr 0. 0.8));
      map3 Shape.triangle (gvec 1.5) (gvec 1.5) (gvec 1.5);
    ]

let gxform =
  let open QCheck.Gen in
  map3
    (fun r s t -> Transform.then_ (Transform.then_ (Transform.scale s) (Transform.rotate r)) (Transform.translate t))
    (gvec 180.) (map3 Vec3.make (fr 0.4 2.5) (fr 0.4 2.5) (fr 0.4 2.5)) (gvec 2.)

(* A ray from a point around the scene aimed near the origin. *)
let gray =
  let open QCheck.Gen in
  map2 (fun o target -> Ray.make o (Vec3.sub target o)) (gvec 8.) (gvec 1.5)

(* Distance-like residual of a point (object space) from the surface. *)
let residual (s : Shape.t) (p : Vec3.t) =
  match s with
  | Shape.Sphere { center; radius } -> Float.abs (Vec3.dist p center -. radius)
  | Shape.Plane { normal; offset } -> Float.abs (Vec3.dot normal p -. offset)
  | Shape.Box { lo; hi } ->
      let out = Vec3.length (Vec3.sub p (Vec3.max lo (Vec3.min hi p))) in
      let face =
        List.fold_left Float.min infinity
          [ Float.abs (p.x -. lo.x); Float.abs (p.x -. hi.x); Float.abs (p.y -. lo.y);
            Float.abs (p.y -. hi.y); Float.abs (p.z -. lo.z); Float.abs (p.z -. hi.z) ]
      in
      Float.max out face
  | Shape.Cone { base; axis; length; r0; r1; open_; _ } ->
      let o = Vec3.sub p base in
      let z = Vec3.dot o axis in
      let rho = Vec3.length (Vec3.madd o (-.z) axis) in
      let rz = r0 +. ((r1 -. r0) *. z /. length) in
      let side = if z >= -1e-9 && z <= length +. 1e-9 then Float.abs (rho -. rz) else infinity in
      let cap zc rc = if open_ || rho > rc +. 1e-9 then infinity else Float.abs (z -. zc) in
      Float.min side (Float.min (cap 0. r0) (cap length r1))
  | Shape.Torus { major; minor } ->
      let rho = Float.sqrt ((p.x *. p.x) +. (p.z *. p.z)) -. major in
      Float.abs (Float.sqrt ((rho *. rho) +. (p.y *. p.y)) -. minor)
  | Shape.Disc { center; normal; radius; hole } ->
      let o = Vec3.sub p center in
      let h = Vec3.dot o normal in
      let d = Vec3.length (Vec3.madd o (-.h) normal) in
      if d > radius +. 1e-9 || d < hole -. 1e-9 then infinity else Float.abs h
  | Shape.Triangle { a; b; c; n } | Shape.Smooth_triangle { a; b; c; na = n; _ } ->
      let n = if Vec3.length n = 0. then n else Vec3.normalize (Vec3.cross (Vec3.sub b a) (Vec3.sub c a)) in
      ignore c;
      Float.abs (Vec3.dot (Vec3.sub p a) n)
  | Shape.Mesh _ -> 0.

let closed = function
  | Shape.Sphere _ | Shape.Box _ | Shape.Torus _ -> true
  | Shape.Cone { open_; _ } -> not open_
  | _ -> false

let shape_name (s : Shape.t) =
  match s with
  | Shape.Sphere _ -> "sphere" | Shape.Plane _ -> "plane" | Shape.Box _ -> "box"
  | Shape.Cone _ -> "cone" | Shape.Torus _ -> "torus" | Shape.Disc _ -> "disc"
  | Shape.Triangle _ -> "triangle" | Shape.Smooth_triangle _ -> "smooth_triangle" | Shape.Mesh _ -> "mesh"

(* Scene text through the real parser and compiler. *)
let scene_of_string src =
  match Camlray_lang.Parse.string src with
  | Error d -> failwith (Camlray_lang.Diag.to_string d)
  | Ok sdl -> (
      match Camlray_lang.Compile.scene sdl with
      | Ok s -> s
      | Error d -> failwith (Camlray_lang.Diag.to_string d))
