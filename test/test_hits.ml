(* Ray-shape hits against hand-computed values. *)
open Camlray

let v = Vec3.make
let ray o d = Ray.make o d
let checkf msg e a = Alcotest.(check (float 1e-9)) msg e a

let units =
  [
    Alcotest.test_case "sphere hit head-on" `Quick (fun () ->
        let s = Shape.sphere (v 0. 0. 5.) 1. in
        checkf "t" 4. (Shape.intersect s (ray Vec3.zero Vec3.unit_z) 0. infinity));
    Alcotest.test_case "sphere hit with an unnormalised direction is in its units" `Quick (fun () ->
        let s = Shape.sphere (v 0. 0. 5.) 1. in
        checkf "t" 2. (Shape.intersect s (ray Vec3.zero (v 0. 0. 2.)) 0. infinity));
    Alcotest.test_case "sphere off-axis: t = 5 - sqrt(1 - 0.6^2)" `Quick (fun () ->
        let s = Shape.sphere (v 0. 0. 5.) 1. in
        checkf "t" (5. -. 0.8) (Shape.intersect s (ray (v 0.6 0. 0.) Vec3.unit_z) 0. infinity));
    Alcotest.test_case "sphere from inside returns the far root" `Quick (fun () ->
        let s = Shape.sphere Vec3.zero 2. in
        checkf "t" 2. (Shape.intersect s (ray Vec3.zero Vec3.unit_x) 0. infinity));
    Alcotest.test_case "sphere miss and tmax" `Quick (fun () ->
        let s = Shape.sphere (v 0. 0. 5.) 1. in
        checkf "miss" infinity (Shape.intersect s (ray (v 2. 0. 0.) Vec3.unit_z) 0. infinity);
        checkf "tmax" infinity (Shape.intersect s (ray Vec3.zero Vec3.unit_z) 0. 3.9));
    Alcotest.test_case "sphere normal is outward unit" `Quick (fun () ->
        let n = Shape.normal (Shape.sphere (v 1. 0. 0.) 2.) (v 1. 2. 0.) (Hit.create infinity) in
        checkf "y" 1. n.y;
        checkf "len" 1. (Vec3.length n));
    Alcotest.test_case "plane {<0,2,0>, 1} is y = 1 (normal normalised first)" `Quick (fun () ->
        let p = Shape.plane (v 0. 2. 0.) 1. in
        checkf "t" 4. (Shape.intersect p (ray (v 0. 5. 0.) (v 0. (-1.) 0.)) 0. infinity);
        Alcotest.(check bool) "inside below" true (Shape.inside p (v 0. 0.5 0.));
        Alcotest.(check bool) "outside above" false (Shape.inside p (v 0. 1.5 0.)));
    Alcotest.test_case "plane parallel ray misses" `Quick (fun () ->
        let p = Shape.plane Vec3.unit_y 0. in
        checkf "t" infinity (Shape.intersect p (ray (v 0. 1. 0.) Vec3.unit_x) 0. infinity));
    Alcotest.test_case "transformed sphere: scale 2 translate 3x" `Quick (fun () ->
        let xform = Transform.then_ (Transform.scale (v 2. 2. 2.)) (Transform.translate (v 3. 0. 0.)) in
        let o = Object.make ~xform (Shape.sphere Vec3.zero 1.) in
        checkf "t" 1. (Object.intersect o (ray (v 0. 0. 0.) Vec3.unit_x) 0. infinity);
        let n = Object.normal o (v 1. 0. 0.) (Hit.create infinity) in
        checkf "nx" (-1.) n.x);
  ]

let tests = ("hits", units)
