(* Shapes: hand-computed hits for each shape, then qcheck properties on
   random transformed shapes: hits lie on the surface, normals are unit,
   perpendicular to the surface and point outward. *)
open Camlray
open Geom_gen

let close ?(eps = 1e-9) a b = Float.abs (a -. b) <= eps *. (1. +. Float.abs a +. Float.abs b)
let vclose ?(eps = 1e-9) (a : Vec3.t) (b : Vec3.t) = close ~eps a.x b.x && close ~eps a.y b.y && close ~eps a.z b.z

(* [case name shape origin dir t normal]: the first hit and its normal. *)
let case name s o d t n =
  Alcotest.test_case name `Quick (fun () ->
      let r = Ray.make o d in
      let h = Hit.create infinity in
      let got = Shape.hit s r 0. h in
      match t with
      | None -> Alcotest.(check bool) "no hit" false got
      | Some t ->
          Alcotest.(check bool) "hit" true got;
          Alcotest.(check (float 1e-9)) "distance" t h.t;
          let nn = Shape.normal s (Ray.at r h.t) h in
          if not (vclose ~eps:1e-9 nn n) then
            Alcotest.failf "normal %s, expected %s" (Vec3.to_string nn) (Vec3.to_string n))

let z = Vec3.unit_z and y = Vec3.unit_y and x = Vec3.unit_x
let down = Vec3.neg y
let s5 = Float.sqrt 5.

let hand =
  [
    case "sphere front" (Shape.sphere Vec3.zero 1.) (v 0. 0. (-5.)) z (Some 4.) (Vec3.neg z);
    case "sphere from inside" (Shape.sphere Vec3.zero 1.) Vec3.zero z (Some 1.) z;
    case "sphere miss" (Shape.sphere Vec3.zero 1.) (v 0. 1.01 (-5.)) z None x;
    case "sphere, unnormalised direction" (Shape.sphere (v 0. 0. 3.) 1.) Vec3.zero (v 0. 0. 2.) (Some 1.) (Vec3.neg z);
    case "plane y=1" (Shape.plane (v 0. 2. 0.) 1.) (v 0. 5. 0.) down (Some 4.) y;
    case "plane parallel" (Shape.plane y 1.) Vec3.zero x None y;
    case "box front face" (Shape.box (v 1. 1. 1.) (v (-1.) (-1.) (-1.))) (v 0.5 0.2 (-5.)) z (Some 4.) (Vec3.neg z);
    case "box from inside" (Shape.box (v (-1.) (-1.) (-1.)) (v 1. 1. 1.)) Vec3.zero x (Some 1.) x;
    case "box miss" (Shape.box (v (-1.) (-1.) (-1.)) (v 1. 1. 1.)) (v 1.5 0. (-5.)) z None x;
    case "cylinder side" (Shape.cylinder Vec3.zero (v 0. 2. 0.) 1.) (v 0. 1. (-5.)) z (Some 4.) (Vec3.neg z);
    case "cylinder top cap" (Shape.cylinder Vec3.zero (v 0. 2. 0.) 1.) (v 0.5 5. 0.) down (Some 3.) y;
    case "cylinder open: no cap" (Shape.cylinder ~open_:true Vec3.zero (v 0. 2. 0.) 1.) (v 0.5 5. 0.) down None y;
    case "open cylinder seen from inside" (Shape.cylinder ~open_:true Vec3.zero (v 0. 2. 0.) 1.) (v 0. 1. 0.) z
      (Some 1.) z;
    case "cone side" (Shape.cone Vec3.zero 1. (v 0. 2. 0.) 0.) (v 0. 1. (-5.)) z (Some 4.5)
      (v 0. (1. /. s5) (-2. /. s5));
    case "cone base cap" (Shape.cone Vec3.zero 1. (v 0. 2. 0.) 0.) (v 0.5 (-3.) 0.) y (Some 3.) down;
    case "torus outer" (Shape.torus 2. 0.5) (v (-5.) 0. 0.) x (Some 2.5) (Vec3.neg x);
    case "torus through the hole" (Shape.torus 2. 0.5) (v 0. 5. 0.) down None y;
    case "torus from above" (Shape.torus 2. 0.5) (v 2. 5. 0.) down (Some 4.5) y;
    case "torus grazing the top" (Shape.torus 2. 0.5) (v (-5.) 0.5 0.) x (Some 3.) y;
    case "torus just above" (Shape.torus 2. 0.5) (v (-5.) 0.500001 0.) x None y;
    case "disc" (Shape.disc ~hole:0.5 Vec3.zero y 1.) (v 0.75 1. 0.) down (Some 1.) y;
    case "disc hole" (Shape.disc ~hole:0.5 Vec3.zero y 1.) (v 0.25 1. 0.) down None y;
    case "triangle" (Shape.triangle Vec3.zero x y) (v 0.2 0.2 (-1.)) z (Some 1.) z;
    case "triangle outside" (Shape.triangle Vec3.zero x y) (v 0.6 0.6 (-1.)) z None z;
    case "smooth triangle normal interpolates" (Shape.smooth_triangle Vec3.zero x x y y z)
      (v 0.5 0.5 (-1.)) z (Some 1.) (Vec3.normalize (v 0. 1. 1.));
  ]

let inside_cases =
  let t name s p want = Alcotest.test_case name `Quick (fun () -> Alcotest.(check bool) name want (Shape.inside s p)) in
  [
    t "plane: opposite the normal is inside" (Shape.plane y 1.) (v 0. 0. 0.) true;
    t "plane: along the normal is outside" (Shape.plane y 1.) (v 0. 2. 0.) false;
    t "disc: behind the normal is inside" (Shape.disc Vec3.zero y 1.) (v 5. (-1.) 5.) true;
    t "disc: in front is outside" (Shape.disc Vec3.zero y 1.) (v 0. 1. 0.) false;
    t "open cylinder is solid" (Shape.cylinder ~open_:true Vec3.zero (v 0. 2. 0.) 1.) (v 0. 1. 0.) true;
    t "torus tube" (Shape.torus 2. 0.5) (v 2. 0.2 0.) true;
    t "torus hole" (Shape.torus 2. 0.5) Vec3.zero false;
    t "triangle has no inside" (Shape.triangle Vec3.zero x y) (v 0.2 0.2 0.) false;
  ]

let gcase = QCheck.Gen.(triple gshape gxform gray)

let print (s, xf, (r : Ray.t)) =
  Printf.sprintf "%s %s ray %s -> %s" (shape_name s) (Transform.to_string xf) (Vec3.to_string r.origin)
    (Vec3.to_string r.dir)

let arb = QCheck.make ~print gcase

(* hit, leaf normal and object-space point for a transformed shape *)
let hit_of s xf r =
  let o = Object.make ~xform:xf s in
  let h = Hit.create infinity in
  if Object.hit o r 1e-9 h (Object.found o) then
    let p = Ray.at r h.t in
    Some (o, h, p, Object.normal o p h)
  else None

let props =
  [
    QCheck.Test.make ~name:"hits of transformed shapes lie on the surface" ~count:3000 arb (fun (s, xf, r) ->
        match hit_of s xf r with
        | None -> true
        | Some (_, _, p, _) ->
            let q = Transform.inv_point xf p in
            let res = residual s q in
            if res > 1e-6 then QCheck.Test.fail_reportf "residual %g at %s" res (Vec3.to_string q);
            true);
    QCheck.Test.make ~name:"normals are unit and perpendicular to the surface" ~count:3000 arb (fun (s, xf, r) ->
        match hit_of s xf r with
        | None -> true
        | Some (_, h, p, n) ->
            if Float.abs (Vec3.length n -. 1.) > 1e-9 then QCheck.Test.fail_reportf "|n| = %g" (Vec3.length n);
            (* two nearby rays hitting the same part: the chord is tangent *)
            let ok = ref true in
            List.iter
              (fun e ->
                let r' = Ray.make r.origin (Vec3.madd r.dir 1e-5 e) in
                match hit_of s xf r' with
                | Some (_, h', p', _) when h'.id = h.id ->
                    let d = Vec3.sub p' p in
                    let l = Vec3.length d in
                    if l > 0. && l < 1e-3 && Float.abs (Vec3.dot d n) > 2e-2 *. l then ok := false
                | _ -> ())
              [ x; y; z ];
            !ok);
    QCheck.Test.make ~name:"normals of closed solids point outward" ~count:3000 arb (fun (s, xf, r) ->
        QCheck.assume (closed s);
        match hit_of s xf r with
        | None -> true
        | Some (o, _, p, n) ->
            let e = 1e-5 in
            (* a step along the normal leaves the solid (a step against it may
               leave too near an edge, so it is not checked) *)
            not (Object.inside o (Vec3.madd p e n)));
    QCheck.Test.make ~name:"every crossing found in order (sphere: 0 or 2)" ~count:1000
      QCheck.(make ~print:(fun (_, r) -> Vec3.to_string r.Ray.origin) Gen.(pair gxform gray))
      (fun (xf, r) ->
        let o = Object.make ~xform:xf (Shape.sphere Vec3.zero 1.) in
        let ts = ref [] in
        ignore (Object.crossings o r 0. infinity (fun _ t -> ts := t :: !ts; true));
        let q = Transform.inv_point xf r.origin in
        let inside = Vec3.length q < 1. in
        match List.rev !ts with
        | [] -> not inside
        | [ _ ] -> inside
        | [ a; b ] -> a < b && not inside
        | _ -> false);
  ]

let folded =
  Alcotest.test_case "a sphere under a similarity is stored moved" `Quick (fun () ->
      let xf = Transform.then_ (Transform.then_ (Transform.scale (v 2. 2. 2.)) (Transform.rotate (v 10. 20. 30.)))
          (Transform.translate (v 3. 0. 0.)) in
      let o = Object.make ~xform:xf (Shape.sphere Vec3.zero 1.) in
      Alcotest.(check bool) "identity transform" true (Transform.is_identity o.xform);
      Alcotest.(check (float 1e-12)) "distance" 8. (Object.intersect o (Ray.make (v 3. 0. (-10.)) z) 0. infinity);
      let o' = Object.make ~xform:(Transform.scale (v 2. 1. 1.)) (Shape.sphere Vec3.zero 1.) in
      Alcotest.(check bool) "an ellipsoid keeps its transform" false (Transform.is_identity o'.xform))

let tests = ("shape", folded :: hand @ inside_cases @ List.map QCheck_alcotest.to_alcotest props)
