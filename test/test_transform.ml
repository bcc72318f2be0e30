open Camlray

let v = Vec3.make
let close_v ?(eps = 1e-9) (a : Vec3.t) (b : Vec3.t) = Vec3.dist a b <= eps

let check_v msg a b =
  if not (close_v a b) then Alcotest.failf "%s: expected %s, got %s" msg (Vec3.to_string b) (Vec3.to_string a)

let gen_transform =
  let open QCheck.Gen in
  let comp = float_range (-3.) 3. in
  let nonzero = map (fun x -> if Float.abs x < 0.2 then 0.2 +. x else x) comp in
  let step =
    oneof
      [ map3 (fun a b c -> Transform.translate (v a b c)) comp comp comp;
        map3 (fun a b c -> Transform.scale (v a b c)) nonzero nonzero nonzero;
        map3 (fun a b c -> Transform.rotate (v (60. *. a) (60. *. b) (60. *. c))) comp comp comp ]
  in
  map (List.fold_left Transform.then_ Transform.identity) (list_size (int_range 1 5) step)

let arb_t = QCheck.make ~print:Transform.to_string gen_transform
let gen_v = QCheck.Gen.(map3 v (float_range (-5.) 5.) (float_range (-5.) 5.) (float_range (-5.) 5.))
let arb_v = QCheck.make ~print:Vec3.to_string gen_v

let props =
  [
    QCheck.Test.make ~name:"inverse undoes the transform (points)" ~count:500
      (QCheck.pair arb_t arb_v) (fun (t, p) ->
        close_v ~eps:1e-8 (Transform.inv_point t (Transform.point t p)) p);
    QCheck.Test.make ~name:"transform { T inverse } is the inverse" ~count:300
      (QCheck.pair arb_t arb_v) (fun (t, p) ->
        close_v ~eps:1e-8 (Transform.point (Transform.inverse t) (Transform.point t p)) p);
    QCheck.Test.make ~name:"normals stay perpendicular to transformed tangents" ~count:500
      (QCheck.triple arb_t arb_v arb_v) (fun (t, n, a) ->
        (* a tangent perpendicular to n *)
        let tangent = Vec3.cross n a in
        let n' = Transform.normal t n and t' = Transform.vector t tangent in
        Float.abs (Vec3.dot n' t') <= 1e-8 *. (1. +. Vec3.length n' *. Vec3.length t'));
    QCheck.Test.make ~name:"then_ composes in written order" ~count:300
      (QCheck.triple arb_t arb_t arb_v) (fun (a, b, p) ->
        close_v ~eps:1e-8 (Transform.point (Transform.then_ a b) p)
          (Transform.point b (Transform.point a p)));
  ]

let units =
  [
    Alcotest.test_case "rotate x*90 sends +y to +z (POV-Ray)" `Quick (fun () ->
        check_v "y" (Transform.vector (Transform.rotate (v 90. 0. 0.)) Vec3.unit_y) Vec3.unit_z);
    Alcotest.test_case "rotate y*90 sends +z to +x and +x to -z" `Quick (fun () ->
        let r = Transform.rotate (v 0. 90. 0.) in
        check_v "z" (Transform.vector r Vec3.unit_z) Vec3.unit_x;
        check_v "x" (Transform.vector r Vec3.unit_x) (v 0. 0. (-1.)));
    Alcotest.test_case "vrotate(x, <90,90,0>) = <0,0,-1>" `Quick (fun () ->
        check_v "x" (Transform.vector (Transform.rotate (v 90. 90. 0.)) Vec3.unit_x) (v 0. 0. (-1.)));
    Alcotest.test_case "scale 2 then translate 3x puts the centre at x=3" `Quick (fun () ->
        let t = Transform.then_ (Transform.scale (v 2. 2. 2.)) (Transform.translate (v 3. 0. 0.)) in
        check_v "c" (Transform.point t Vec3.zero) (v 3. 0. 0.);
        let t' = Transform.then_ (Transform.translate (v 3. 0. 0.)) (Transform.scale (v 2. 2. 2.)) in
        check_v "c'" (Transform.point t' Vec3.zero) (v 6. 0. 0.));
    Alcotest.test_case "matrix is POV-Ray's row-vector form" `Quick (fun () ->
        match Transform.of_pov_matrix [| 1.; 2.; 3.; 4.; 5.; 6.; 7.; 8.; 10.; 1.; 1.; 1. |] with
        | None -> Alcotest.fail "not singular"
        | Some t ->
            (* x' = a x + d y + g z + j, ... *)
            check_v "p" (Transform.point t (v 1. 1. 1.)) (v (1. +. 4. +. 7. +. 1.) (2. +. 5. +. 8. +. 1.) (3. +. 6. +. 10. +. 1.)));
    Alcotest.test_case "a singular matrix is refused" `Quick (fun () ->
        Alcotest.(check bool) "none" true
          (Transform.of_pov_matrix [| 1.; 0.; 0.; 2.; 0.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |] = None));
    Alcotest.test_case "normal of scale <2,1,1> sphere (pov-facts 2)" `Quick (fun () ->
        (* unit sphere scaled <2,1,1>, hit at (1, 0.5, -0.7071): object point (0.5,0.5,-0.7071) *)
        let t = Transform.scale (v 2. 1. 1.) in
        let p_obj = Transform.inv_point t (v 1. 0.5 (-0.70710678)) in
        let n = Vec3.normalize (Transform.normal t p_obj) in
        if not (close_v ~eps:1e-4 n (v 0.2774 0.5547 (-0.7845))) then Alcotest.fail "normal");
  ]

let tests = ("transform", units @ List.map QCheck_alcotest.to_alcotest props)
