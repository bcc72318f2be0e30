(* Generators shared by the geometry tests: random shapes, transforms,
   rays, and the implicit surface equations the hits must satisfy. *)
open Camlray

let v = Vec3.make
let fr lo hi = QCheck.Gen.float_range lo hi
let gvec r = QCheck.Gen.(map3 Vec3.make (fr (-.r) r) (fr (-.r) r) (fr (-.r) r))

let gdir =
  QCheck.Gen.(
    map (fun d -> if Vec3.length d < 1e-3 then Vec3.unit_z else Vec3.normalize d) (gvec 1.))

(* POV-Ray's documented order of a quartic's 35 terms (the powers of x,
   y, z written out); lower orders follow the same rule *)
let quartic_terms =
  [ "x4"; "x3y"; "x3z"; "x3"; "x2y2"; "x2yz"; "x2y"; "x2z2"; "x2z"; "x2"; "xy3"; "xy2z"; "xy2"; "xyz2";
    "xyz"; "xy"; "xz3"; "xz2"; "xz"; "x"; "y4"; "y3z"; "y3"; "y2z2"; "y2z"; "y2"; "yz3"; "yz2"; "yz";
    "y"; "z4"; "z3"; "z2"; "z"; "" ]

(* the powers of x, y, z in a term's name *)
let powers name =
  let p = [| 0; 0; 0 |] and n = String.length name in
  String.iteri
    (fun i c ->
      let e = if i + 1 < n && name.[i + 1] >= '0' && name.[i + 1] <= '9' then Char.code name.[i + 1] - 48 else 1 in
      match c with 'x' -> p.(0) <- e | 'y' -> p.(1) <- e | 'z' -> p.(2) <- e | _ -> ())
    name;
  (p.(0), p.(1), p.(2))

(* A quartic's coefficients from its monomials ((powers of x, y, z), c) *)
let quartic monos =
  let a = Array.make 35 0. in
  List.iter
    (fun (e, c) ->
      let rec find i = function [] -> invalid_arg "quartic" | t :: r -> if powers t = e then i else find (i + 1) r in
      let i = find 0 quartic_terms in
      a.(i) <- a.(i) +. c)
    monos;
  a

(* The torus of radii r1, r2 (axis y) as a quartic:
   (x^2 + y^2 + z^2 + r1^2 - r2^2)^2 - 4 r1^2 (x^2 + z^2) *)
let torus_quartic r1 r2 =
  let k = (r1 *. r1) -. (r2 *. r2) and r4 = 4. *. r1 *. r1 in
  Algebraic.make 4
    (quartic
       [ ((4, 0, 0), 1.); ((0, 4, 0), 1.); ((0, 0, 4), 1.); ((2, 2, 0), 2.); ((2, 0, 2), 2.); ((0, 2, 2), 2.);
         ((2, 0, 0), (2. *. k) -. r4); ((0, 2, 0), 2. *. k); ((0, 0, 2), (2. *. k) -. r4); ((0, 0, 0), k *. k) ])

(* The quadric x^2/a^2 + y^2/b^2 + z^2/c^2 + e = 0 as an order-2 polynomial
   (terms x^2, xy, xz, x, y^2, yz, y, z^2, z, 1) *)
let quadric a b c e =
  Algebraic.make 2 [| 1. /. (a *. a); 0.; 0.; 0.; 1. /. (b *. b); 0.; 0.; 1. /. (c *. c); 0.; e |]

let galgebraic =
  let open QCheck.Gen in
  oneof
    [
      map2 (fun r1 r2 -> Shape.Algebraic (torus_quartic r1 r2)) (fr 0.5 1.5) (fr 0.1 0.5);
      map3 (fun a b c -> Shape.Algebraic (quadric a b c (-1.))) (fr 0.3 1.5) (fr 0.3 1.5) (fr 0.3 1.5);
      (* a hyperboloid of one sheet: unbounded *)
      map2 (fun a b -> Shape.Algebraic (quadric a (-.b) a (-1.))) (fr 0.3 1.) (fr 0.3 1.);
      (* a rounded cube x^4 + y^4 + z^4 = s^4 *)
      map (fun s -> Shape.Algebraic (Algebraic.make 4 (quartic [ ((4, 0, 0), 1.); ((0, 4, 0), 1.); ((0, 0, 4), 1.);
                                                                  ((0, 0, 0), -.(s ** 4.)) ])))
        (fr 0.4 1.2);
      (* a monkey saddle y = k (x^3 - 3 x z^2): a cubic, unbounded *)
      map (fun k -> Shape.Algebraic (Algebraic.make 3
                                       (Array.init 20 (fun i -> match i with 0 -> -.k | 7 -> 3. *. k | 15 -> 1. | _ -> 0.))))
        (fr 0.1 1.);
    ]

(* blobs of two or three components of positive strength, threshold 0.25 *)
let gblob =
  let open QCheck.Gen in
  let comp =
    oneof
      [
        map3 (fun center radius strength -> Blob.Sphere { center; radius; strength }) (gvec 0.8) (fr 0.5 1.2) (fr 0.5 1.5);
        map3 (fun a d (radius, strength) -> Blob.Cylinder { a; b = Vec3.madd a 1.2 d; radius; strength })
          (gvec 0.8) gdir (pair (fr 0.4 1.) (fr 0.5 1.5));
      ]
  in
  map (fun cs -> Shape.Blob (Blob.make ~threshold:0.25 cs)) (list_size (int_range 2 3) comp)

(* surfaces of revolution of 4 to 7 points, heights rising by 0.2 to
   0.8, radii 0.3 to 1.2, open or closed *)
let gsor =
  let open QCheck.Gen in
  int_range 4 7 >>= fun n ->
  map3
    (fun steps radii open_ ->
      let y = ref (-1.) in
      let pts = List.map2 (fun dy r -> y := !y +. dy; (r, !y)) steps radii in
      match Sor.make ~open_ (Array.of_list pts) with Ok s -> Shape.Sor s | Error e -> failwith e)
    (list_size (return n) (fr 0.2 0.8)) (list_size (return n) (fr 0.3 1.2)) bool

(* a star-shaped outline of 3 to 8 points in a random plane, closed *)
let gpolygon =
  let open QCheck.Gen in
  map3
    (fun c nrm rs ->
      let u = Vec3.normalize (Vec3.cross nrm (if Float.abs nrm.Vec3.x < 0.9 then Vec3.unit_x else Vec3.unit_y)) in
      let v = Vec3.cross nrm u in
      let k = List.length rs in
      let pts =
        List.mapi
          (fun i r ->
            let a = 2. *. Float.pi *. Stdlib.float i /. Stdlib.float k in
            Vec3.add c (Vec3.add (Vec3.scale (r *. cos a) u) (Vec3.scale (r *. sin a) v)))
          rs
      in
      let pts = Array.of_list (pts @ [ List.hd pts ]) in
      match Polygon.make pts with Ok (p, _) -> Shape.Polygon p | Error e -> failwith e)
    (gvec 0.5) gdir
    (list_size (int_range 3 8) (fr 0.4 1.5))

(* a 2..6 x 2..6 grid of random heights, sometimes a water level *)
let gheight_field =
  let open QCheck.Gen in
  int_range 2 6 >>= fun w ->
  int_range 2 6 >>= fun d ->
  map2
    (fun hs water -> Shape.Height_field (Height_field.make ~width:w ~depth:d ~heights:(Array.of_list hs) ~smooth:false ~water))
    (list_size (return (w * d)) (int_range 0 65535))
    (oneof_list [ 0.; 0.; 0.3 ])
(* isosurfaces of distance functions (slope 1) found to 1e-9: a sphere
   and a torus, in a box container just around them *)
let giso =
  let open QCheck.Gen in
  let iso f e =
    Shape.Isosurface
      (Isosurface.make ~fn:(Isosurface.fn_of_closure f)
         ~container:(Isosurface.Box (Vec3.make (-.e.(0)) (-.e.(1)) (-.e.(2)), Vec3.make e.(0) e.(1) e.(2)))
         ~threshold:0. ~accuracy:1e-9 ~max_gradient:1.1 ~open_:false ~max_trace:1)
  in
  oneof
    [
      map (fun r -> iso (fun x y z -> Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) -. r) [| r +. 0.1; r +. 0.1; r +. 0.1 |])
        (fr 0.3 1.5);
      map2
        (fun r1 r2 ->
          let e = r1 +. r2 +. 0.1 in
          iso
            (fun x y z ->
              let q = Float.sqrt ((x *. x) +. (z *. z)) -. r1 in
              Float.sqrt ((q *. q) +. (y *. y)) -. r2)
            [| e; r2 +. 0.1; e |])
        (fr 0.5 1.5) (fr 0.1 0.5);
    ]

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
      galgebraic;
      gblob;
      gsor;
      gpolygon;
      gheight_field;
      giso;
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

(* A height field's hit may lie on a triangle's plane up to 1e-4 grid units
   past its edges (POV-Ray's tolerance): the smallest height difference
   from the planes of the triangles within that reach, object units. *)
let hf_residual f (p : Vec3.t) =
  let w = Height_field.width f and d = Height_field.depth f in
  let sx = float (w - 1) and sz = float (d - 1) in
  let gx = p.x *. sx and gz = p.z *. sz and gy = p.y *. 65536. in
  let h = Height_field.height f in
  let best = ref infinity in
  for cx = Int.max 0 (truncate gx - 1) to Int.min (w - 2) (truncate gx + 1) do
    for cz = Int.max 0 (truncate gz - 1) to Int.min (d - 2) (truncate gz + 1) do
      let s = gx -. float cx and u = gz -. float cz in
      if s >= -2e-4 && u >= -2e-4 && s +. u <= 1.0002 then
        best := Float.min !best (Float.abs (gy -. (h cx cz +. (s *. (h (cx + 1) cz -. h cx cz)) +. (u *. (h cx (cz + 1) -. h cx cz)))));
      if s <= 1.0002 && u <= 1.0002 && s +. u >= 0.9998 then
        let y4 = h (cx + 1) (cz + 1) in
        best :=
          Float.min !best
            (Float.abs (gy -. (y4 +. ((1. -. s) *. (h cx (cz + 1) -. y4)) +. ((1. -. u) *. (h (cx + 1) cz -. y4)))))
    done
  done;
  !best /. 65536.

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
  | Shape.Polygon pg -> Float.abs (Vec3.dot (Polygon.normal pg) (Vec3.sub p (Polygon.point pg)))
  | Shape.Height_field f -> hf_residual f p
  | Shape.Mesh _ | Shape.Text _ | Shape.Prism _ | Shape.Lathe _ | Shape.Sor _ | Shape.Superellipsoid _ | Shape.Julia _ -> 0.
  | Shape.Isosurface i -> (
      (* the container's faces, or the function (a distance: slope 1) *)
      let f = Float.abs (Isosurface.value i p.x p.y p.z) in
      let lo, hi = Isosurface.bounds i in
      let out = Vec3.length (Vec3.sub p (Vec3.max lo (Vec3.min hi p))) in
      let face = Float.min (Float.min (Float.abs (p.x -. lo.x)) (Float.abs (p.x -. hi.x)))
          (Float.min (Float.min (Float.abs (p.y -. lo.y)) (Float.abs (p.y -. hi.y)))
             (Float.min (Float.abs (p.z -. lo.z)) (Float.abs (p.z -. hi.z)))) in
      if out > 0. then out +. f else Float.min f face)
  | Shape.Blob b ->
      (* the field's distance from the generator's threshold over its slope *)
      let f x y z = Blob.field b x y z in
      let e = 1e-6 in
      let gx = (f (p.x +. e) p.y p.z -. f (p.x -. e) p.y p.z) /. (2. *. e)
      and gy = (f p.x (p.y +. e) p.z -. f p.x (p.y -. e) p.z) /. (2. *. e)
      and gz = (f p.x p.y (p.z +. e) -. f p.x p.y (p.z -. e)) /. (2. *. e) in
      Float.abs (f p.x p.y p.z -. 0.25) /. Float.sqrt ((gx *. gx) +. (gy *. gy) +. (gz *. gz))
  | Shape.Algebraic a ->
      (* the value over the gradient's length: the distance to first order *)
      let g = Vec3.m () in
      Algebraic.gradient_into a p.x p.y p.z g;
      Float.abs (Algebraic.eval a p.x p.y p.z) /. Vec3.length (Vec3.of_m g)

let closed = function
  | Shape.Sphere _ | Shape.Box _ | Shape.Torus _ -> true
  | Shape.Algebraic _ -> false (* inside up to 1e-4 of its value: see test_shape *)
  | Shape.Blob _ -> true
  | Shape.Isosurface _ -> true
  | Shape.Cone { open_; _ } -> not open_
  | _ -> false

let shape_name (s : Shape.t) =
  match s with
  | Shape.Sphere _ -> "sphere" | Shape.Plane _ -> "plane" | Shape.Box _ -> "box"
  | Shape.Cone _ -> "cone" | Shape.Torus _ -> "torus" | Shape.Disc _ -> "disc"
  | Shape.Triangle _ -> "triangle" | Shape.Smooth_triangle _ -> "smooth_triangle" | Shape.Mesh _ -> "mesh"
  | Shape.Algebraic a -> Printf.sprintf "algebraic of order %d" (Algebraic.order a)
  | Shape.Text _ -> "text"
  | Shape.Blob _ -> "blob"
  | Shape.Prism _ -> "prism"
  | Shape.Lathe _ -> "lathe"
  | Shape.Sor _ -> "sor"
  | Shape.Superellipsoid _ -> "superellipsoid"
  | Shape.Julia _ -> "julia_fractal"
  | Shape.Polygon _ -> "polygon"
  | Shape.Height_field _ -> "height_field"
  | Shape.Isosurface _ -> "isosurface"

(* Scene text through the real parser and compiler. *)
let scene_of_string src =
  match Camlray_lang.Parse.string src with
  | Error d -> failwith (Camlray_lang.Diag.to_string d)
  | Ok sdl -> (
      match Camlray_lang.Compile.scene sdl with
      | Ok s -> s
      | Error d -> failwith (Camlray_lang.Diag.to_string d))
