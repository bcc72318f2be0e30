open Camlray

let gen_vec =
  QCheck.Gen.(
    map3 Vec3.make (float_range (-100.) 100.) (float_range (-100.) 100.)
      (float_range (-100.) 100.))

let arb_vec = QCheck.make ~print:Vec3.to_string gen_vec
let close ?(eps = 1e-9) a b = Float.abs (a -. b) <= eps *. (1. +. Float.abs a +. Float.abs b)

let props =
  [
    QCheck.Test.make ~name:"cross is perpendicular to both" ~count:500
      (QCheck.pair arb_vec arb_vec) (fun (a, b) ->
        let c = Vec3.cross a b in
        let s = Vec3.length a *. Vec3.length b in
        Float.abs (Vec3.dot c a) <= 1e-9 *. s *. (1. +. Vec3.length a)
        && Float.abs (Vec3.dot c b) <= 1e-9 *. s *. (1. +. Vec3.length b));
    QCheck.Test.make ~name:"normalize gives unit length" ~count:500 arb_vec
      (fun a ->
        QCheck.assume (Vec3.length a > 1e-6);
        close (Vec3.length (Vec3.normalize a)) 1.);
    QCheck.Test.make ~name:"dot is symmetric and bilinear" ~count:500
      (QCheck.triple arb_vec arb_vec arb_vec) (fun (a, b, c) ->
        close (Vec3.dot a b) (Vec3.dot b a)
        && close ~eps:1e-7
             (Vec3.dot a (Vec3.add b c))
             (Vec3.dot a b +. Vec3.dot a c));
    QCheck.Test.make ~name:"|a x b|^2 + (a.b)^2 = |a|^2 |b|^2" ~count:500
      (QCheck.pair arb_vec arb_vec) (fun (a, b) ->
        let c = Vec3.cross a b in
        close ~eps:1e-7
          (Vec3.length2 c +. (Vec3.dot a b ** 2.))
          (Vec3.length2 a *. Vec3.length2 b));
  ]

let unit_tests =
  [
    Alcotest.test_case "x cross y = z (POV-Ray's formula)" `Quick (fun () ->
        let c = Vec3.cross Vec3.unit_x Vec3.unit_y in
        Alcotest.(check (float 0.)) "x" 0. c.x;
        Alcotest.(check (float 0.)) "y" 0. c.y;
        Alcotest.(check (float 0.)) "z" 1. c.z);
    Alcotest.test_case "normalize of zero stays zero" `Quick (fun () ->
        let n = Vec3.normalize Vec3.zero in
        Alcotest.(check (float 0.)) "len" 0. (Vec3.length n));
  ]

let tests = ("vec3", unit_tests @ List.map QCheck_alcotest.to_alcotest props)
