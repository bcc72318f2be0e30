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
    (* povray 3.7's vrotate(<1,2,3>, <a,a,a>) and a composed transform's
       point, printed to 20 decimals: the same doubles (angles times
       pi/180 as one constant, sums with the translation last) *)
    Alcotest.test_case "rotations and compositions round as POV-Ray's" `Quick (fun () ->
        let pov =
          [ (3., (1.06299805440617212149, 1.89848602956449674650, 3.04397535007711939059));
            (6., (1.14583249121694530359, 1.80511914193489242386, 3.07060462865081396089));
            (12., (1.36105590979370250082, 1.65163167941634725366, 3.06914313872194277621));
            (19., (1.66994658316170041523, 1.54202588143230379103, 2.97210945127858483517));
            (23., (1.86030394739577831231, 1.51622772753601120499, 2.87059622753787380134));
            (41., (2.64128033561921204964, 1.68816975315989337147, 2.04296869119116131230)) ]
        in
        let exact msg (x, y, z) (p : Vec3.t) = Alcotest.(check (list (float 0.))) msg [ x; y; z ] [ p.x; p.y; p.z ] in
        List.iter
          (fun (a, e) -> exact (Printf.sprintf "vrotate by %g" a) e (Transform.vector (Transform.rotate (v a a a)) (v 1. 2. 3.)))
          pov;
        let t =
          List.fold_left Transform.then_ Transform.identity
            [ Transform.translate (v 0.1 0.2 0.3); Transform.rotate (v 13. 27. 41.); Transform.scale (v 0.7 0.7 0.7);
              Transform.translate (v 0.33 0.77 1.1) ]
        in
        exact "composed" (1.25906859879298460569, 3.00239315910594539716, 3.50028171719775782478)
          (Transform.point t (v 1.1 2.3 3.7));
        (* vaxis_rotate: POV-Ray's axis rotation, term by term (20 decimals) *)
        exact "vaxis_rotate 37" (-1.16084631453716369265, 1.17593043189071377874, 3.35702598342324476377)
          (Transform.vector (Transform.axis_rotate (v 0.3 (-0.7) 0.2) 37.) (v 1. 2. 3.));
        exact "vaxis_rotate 123.4" (3.05392585088735701859, -1.40048876894597063014, 0.04656291805861434430)
          (Transform.vector (Transform.axis_rotate (v 1. 1. 1.) 123.4) (v (-1.5) 0.2 3.));
        exact "vaxis_rotate 41" (-0.05574084777582424821, 0.21654781894360514150, 0.29999999999999998890)
          (Transform.vector (Transform.axis_rotate (v 0. 0. 1.) 41.) (v 0.1 0.2 0.3)));
    Alcotest.test_case "normal of scale <2,1,1> sphere (pov-facts 2)" `Quick (fun () ->
        (* unit sphere scaled <2,1,1>, hit at (1, 0.5, -0.7071): object point (0.5,0.5,-0.7071) *)
        let t = Transform.scale (v 2. 1. 1.) in
        let p_obj = Transform.inv_point t (v 1. 0.5 (-0.70710678)) in
        let n = Vec3.normalize (Transform.normal t p_obj) in
        if not (close_v ~eps:1e-4 n (v 0.2774 0.5547 (-0.7845))) then Alcotest.fail "normal");
  ]

let tests = ("transform", units @ List.map QCheck_alcotest.to_alcotest props)
