(* POV-Ray's camera placement, checked through the scene language. The
   expected values are POV-Ray's own (pov-facts.md section 1). *)
open Camlray

let cam text = (Helpers.compile_string ("#version 3.7;\n" ^ text)).camera

let hit_x c sx sy z =
  let r = Camera.ray c sx sy in
  let t = (z -. r.origin.z) /. r.dir.z in
  Ray.at r t

let units =
  [
    Alcotest.test_case "default camera: right 1.33, plane z=1 mapping" `Quick (fun () ->
        let c = cam "" in
        (* 4x3 image, pixel 0: sx = (0.5)/4 - 0.5 *)
        let sx, sy = Camera.pixel_coords ~width:4 ~height:3 0.5 0.5 in
        let p = hit_x c sx sy 1. in
        Alcotest.(check (float 1e-9)) "x" (1.33 *. sx) p.x;
        Alcotest.(check (float 1e-9)) "y" (0.5 -. (0.5 /. 3.)) p.y);
    Alcotest.test_case "angle 60: leftmost pixel centre hits x = -2.16506" `Quick (fun () ->
        let c = cam "camera { location <0,0,-5> look_at 0 angle 60 }" in
        let sx, sy = Camera.pixel_coords ~width:4 ~height:3 0.5 1.5 in
        let p = hit_x c sx sy 0. in
        Alcotest.(check (float 1e-4)) "x" (-2.16506) p.x);
    Alcotest.test_case "direction and look_at order does not matter" `Quick (fun () ->
        let a = cam "camera { direction 2*z look_at <1,1,3> }" in
        let b = cam "camera { look_at <1,1,3> direction 2*z }" in
        Alcotest.(check bool) "same" true (a = b));
    Alcotest.test_case "sky <1,1,0> rolls the view 45 degrees" `Quick (fun () ->
        let c = cam "camera { location <0,0,-5> look_at 0 sky <1,1,0> }" in
        let u = Vec3.normalize c.up in
        Alcotest.(check (float 1e-9)) "ux" (sqrt 0.5) u.x;
        Alcotest.(check (float 1e-9)) "uy" (sqrt 0.5) u.y);
    Alcotest.test_case "orthographic sizing from look_at distance: width 6.65" `Quick (fun () ->
        let c = cam "camera { orthographic location <0,0,-5> look_at 0 }" in
        Alcotest.(check (float 1e-9)) "width" 6.65 (Vec3.length c.right));
    Alcotest.test_case "orthographic with angle 60: width 2*5*tan 30" `Quick (fun () ->
        let c = cam "camera { orthographic location <0,0,-5> look_at 0 angle 60 }" in
        Alcotest.(check (float 1e-9)) "width" (10. *. tan (Float.pi /. 6.)) (Vec3.length c.right));
    Alcotest.test_case "orthographic with explicit right and up keeps them" `Quick (fun () ->
        let c = cam "camera { orthographic location <0,0,-5> look_at 0 right 8*x up 6*y }" in
        Alcotest.(check (float 1e-9)) "w" 8. (Vec3.length c.right);
        Alcotest.(check (float 1e-9)) "h" 6. (Vec3.length c.up));
    Alcotest.test_case "a mirrored right stays mirrored after look_at" `Quick (fun () ->
        let c = cam "camera { right -1.33*x location <0,0,-5> look_at <0,0,0> }" in
        Alcotest.(check bool) "negative x" true (c.right.x < 0.));
    Alcotest.test_case "looking along the sky: right kept, mirrored by the handedness as POV-Ray" `Quick
      (fun () ->
        (* POV-Ray 3.7's pictures (checked with povray: identical renders):
           default up and direction keep +x right and turn up to +z; up z
           with the default direction z (handedness 0) mirrors right *)
        let a = cam "camera { location <0,10,0> look_at 0 }" in
        Alcotest.(check (float 1e-9)) "a: right +x" 1.33 a.right.x;
        Alcotest.(check (float 1e-9)) "a: up +z" 1. (Vec3.normalize a.up).z;
        let b = cam "camera { orthographic location <0,10,0> look_at 0 right x*8 up z*6 }" in
        Alcotest.(check (float 1e-9)) "b: right -x" (-8.) b.right.x;
        Alcotest.(check (float 1e-9)) "b: up +z" 6. b.up.z;
        let c = cam "camera { location <0,-10,0> look_at 0 right x*1.33 up z direction -z }" in
        (* handedness (z x -z) . x = 0: mirrored; up = d x r, taken
           before the mirroring: y x x = -z *)
        Alcotest.(check (float 1e-9)) "c: right -x" (-1.33) c.right.x;
        Alcotest.(check (float 1e-9)) "c: up -z" (-1.) (Vec3.normalize c.up).z);
    Alcotest.test_case "cylinder 1: the ray turns by x * angle about up, y is flat" `Quick (fun () ->
        let c = cam "camera { cylinder 1 location <0,0,-5> look_at 0 up 2*y angle 120 }" in
        let r = Camera.ray c 0.25 0.1 in
        (* 0.25 of 120 degrees = 30 degrees right of +z; up 2 * 0.1 *)
        let d = Vec3.make (sin (Float.pi /. 6.)) 0.2 (cos (Float.pi /. 6.)) in
        Alcotest.(check (float 1e-9)) "dx" 0. (Vec3.dist r.dir (Vec3.normalize d));
        Alcotest.(check (float 1e-12)) "origin" 0. (Vec3.dist r.origin (Vec3.make 0. 0. (-5.))));
    Alcotest.test_case "cylinder 2: the ray turns by y * angle about right; default angle 90" `Quick
      (fun () ->
        let c = cam "camera { cylinder 2 location <0,0,-5> look_at 0 right 2*x }" in
        let r = Camera.ray c 0.1 (-0.5) in
        (* the bottom edge looks 45 degrees down; x is flat, scaled by |right| *)
        let d = Vec3.make 0.2 (-.sqrt 0.5) (sqrt 0.5) in
        Alcotest.(check (float 1e-9)) "dir" 0. (Vec3.dist r.dir (Vec3.normalize d)));
    Alcotest.test_case "cylinder 3 and 4 slide the eye along the axis" `Quick (fun () ->
        let c3 = cam "camera { cylinder 3 location <0,0,-5> look_at 0 up 3*y angle 180 }" in
        let r = Camera.ray c3 0.5 0.25 in
        Alcotest.(check (float 1e-9)) "eye" 0. (Vec3.dist r.origin (Vec3.make 0. 0.75 (-5.)));
        Alcotest.(check (float 1e-9)) "dir +x" 0. (Vec3.dist r.dir Vec3.unit_x);
        let c4 = cam "camera { cylinder 4 location <0,0,-5> look_at 0 right 4*x angle 180 }" in
        let r = Camera.ray c4 (-0.25) 0.5 in
        Alcotest.(check (float 1e-9)) "eye" 0. (Vec3.dist r.origin (Vec3.make (-1.) 0. (-5.)));
        Alcotest.(check (float 1e-9)) "dir +y" 0. (Vec3.dist r.dir Vec3.unit_y));
    Alcotest.test_case "fisheye: the circle's edge looks angle/2 away; outside it, no ray" `Quick
      (fun () ->
        let c = cam "camera { fisheye location 0 look_at z right x up y angle 180 }" in
        let r = Camera.ray c 0.5 0. in
        Alcotest.(check (float 1e-9)) "edge looks right" 0. (Vec3.dist r.dir Vec3.unit_x);
        let r = Camera.ray c 0. 0.25 in
        (* half-way out: 45 degrees up *)
        Alcotest.(check (float 1e-9)) "up 45" 0. (Vec3.dist r.dir (Vec3.normalize (Vec3.make 0. 1. 1.)));
        Alcotest.(check bool) "corner unseen" false (Camera.sees c 0.4 0.4);
        Alcotest.(check bool) "inside seen" true (Camera.sees c 0.3 0.3));
    Alcotest.test_case "ultra_wide_angle: sin and cos of angle * x, angle * y * |up|/|right|" `Quick
      (fun () ->
        let c = cam "camera { ultra_wide_angle location 0 look_at z right 4/3*x up y angle 180 }" in
        let r = Camera.ray c 0.5 0. in
        Alcotest.(check (float 1e-9)) "edge looks right" 0. (Vec3.dist r.dir Vec3.unit_x);
        let r = Camera.ray c 0. 0.5 in
        let a = Float.pi /. 2. *. 0.75 in
        Alcotest.(check (float 1e-9)) "top" 0. (Vec3.dist r.dir (Vec3.make 0. (sin a) (cos a))));
    Alcotest.test_case "panoramic: 180 degrees across, tan of the height up" `Quick (fun () ->
        let c = cam "camera { panoramic location 0 look_at z right x up y }" in
        Alcotest.(check (float 1e-9)) "centre" 0. (Vec3.dist (Camera.ray c 0. 0.).dir Vec3.unit_z);
        Alcotest.(check (float 1e-9)) "right edge" 0. (Vec3.dist (Camera.ray c 0.5 0.).dir Vec3.unit_x);
        let r = Camera.ray c 0. 0.25 in
        Alcotest.(check (float 1e-9)) "up 45" 0. (Vec3.dist r.dir (Vec3.normalize (Vec3.make 0. 1. 1.))));
    Alcotest.test_case "spherical: longitude and latitude; 360 by 180 by default, v = h/2" `Quick
      (fun () ->
        let c = cam "camera { spherical location 0 look_at z }" in
        Alcotest.(check (float 1e-9)) "quarter right" 0. (Vec3.dist (Camera.ray c 0.25 0.).dir Vec3.unit_x);
        Alcotest.(check (float 1e-9)) "behind" 0. (Vec3.dist (Camera.ray c 0.5 0.).dir (Vec3.neg Vec3.unit_z));
        let r = Camera.ray c 0.25 0.25 in
        (* 45 degrees up, then turned to the right *)
        Alcotest.(check (float 1e-9)) "up-right" 0. (Vec3.dist r.dir (Vec3.normalize (Vec3.make 1. 1. 0.)));
        let c = cam "camera { spherical location 0 look_at z angle 120 }" in
        let r = Camera.ray c 0. 0.5 in
        (* v = 60: the top edge 30 degrees up *)
        Alcotest.(check (float 1e-9)) "v = h/2" 0. (Vec3.dist r.dir (Vec3.make 0. 0.5 (sqrt 0.75)));
        let c = cam "camera { spherical location 0 look_at z angle 120, 90 }" in
        let r = Camera.ray c 0. 0.5 in
        Alcotest.(check (float 1e-9)) "v given" 0. (Vec3.dist r.dir (Vec3.normalize (Vec3.make 0. 1. 1.))));
    Alcotest.test_case "omnimax: the centre looks ahead, the dome ends 45 degrees under the axis" `Quick
      (fun () ->
        let c = cam "camera { omnimax location 0 look_at z right x up y }" in
        Alcotest.(check (float 1e-9)) "centre" 0. (Vec3.dist (Camera.ray c 0. 0.).dir Vec3.unit_z);
        (* rad 1: POV-Ray's polynomial gives 1.573619 radians *)
        let r = Camera.ray c 0. 0.5 in
        Alcotest.(check (float 1e-9)) "top" (cos 1.573619) r.dir.z;
        Alcotest.(check bool) "top seen" true (Camera.sees c 0. 0.5);
        Alcotest.(check bool) "bottom unseen" false (Camera.sees c 0. (-0.5));
        Alcotest.(check bool) "outside the circle" false (Camera.sees c 0.45 0.45));
    Alcotest.test_case "normal: rays turned as POV-Ray turns them" `Quick (fun () ->
        (* POV-Ray 3.7's directions at the pixel centres of a 4x3 image,
           read back as colours of a sphere around the eye (16-bit PPM,
           file gamma 1: 3e-5 a step) *)
        let c = cam "camera { location 0 direction z right 4/3*x up y normal { gradient <1,0.5,0> 0.8 scale 0.3 } }" in
        let expected =
          [| (-0.50753, 0.23055, 0.83023); (-0.25017, 0.26314, 0.93176); (0.06230, 0.27126, 0.96048);
             (0.35073, 0.25057, 0.90234); (-0.51815, -0.04555, 0.85409); (-0.25441, -0.04671, 0.96597);
             (0.06969, -0.04817, 0.99640); (0.36559, -0.04958, 0.92944); (-0.49502, -0.31499, 0.80978);
             (-0.24309, -0.34792, 0.90546); (0.06041, -0.35802, 0.93176); (0.34060, -0.34084, 0.87625) |]
        in
        Array.iteri
          (fun i (ex, ey, ez) ->
            let sx, sy = Camera.pixel_coords ~width:4 ~height:3 (float_of_int (i mod 4) +. 0.5) (float_of_int (i / 4) +. 0.5) in
            let d = (Camera.ray c sx sy).dir in
            Scn.check_floats ~eps:1e-4 (Printf.sprintf "pixel %d" i) [ ex; ey; ez ] [ d.x; d.y; d.z ])
          expected;
        (* in place, through the lens path too, and nothing allocated *)
        let o = Vec3.m () and d = Vec3.m () in
        ignore (Camera.ray_into c 0.1 0.2 o d);
        let r = Camera.ray c 0.1 0.2 in
        Scn.check_floats ~eps:1e-15 "ray_into = ray" [ r.dir.x; r.dir.y; r.dir.z ] [ d.mx; d.my; d.mz ];
        ignore (Camera.lens_into c 0.1 0.2 0.5 0.5 o d);
        Scn.check_floats ~eps:1e-15 "lens_into, no aperture" [ r.dir.x; r.dir.y; r.dir.z ] [ d.mx; d.my; d.mz ];
        let before = Gc.minor_words () in
        for i = 1 to 1000 do
          ignore (Camera.ray_into c (float_of_int i *. 1e-3 -. 0.5) 0.2 o d)
        done;
        let words = Gc.minor_words () -. before in
        if words > 0. then Alcotest.failf "%.0f words for 1000 camera rays with a normal" words;
        (* a flat normal leaves the rays alone *)
        let flat = cam "camera { location 0 direction z right 4/3*x up y normal { gradient x 0 } }" in
        let plain = cam "camera { location 0 direction z right 4/3*x up y }" in
        let a = (Camera.ray flat 0.3 (-0.2)).dir and b = (Camera.ray plain 0.3 (-0.2)).dir in
        Scn.check_floats ~eps:1e-12 "amount 0" [ b.x; b.y; b.z ] [ a.x; a.y; a.z ]);
    Alcotest.test_case "every camera type: rays written in place equal Camera.ray" `Quick (fun () ->
        let o = Vec3.m () and d = Vec3.m () in
        List.iter
          (fun kind ->
            let c = cam ("camera { " ^ kind ^ " location <1,2,-5> look_at <0,1,0> rotate 10*z }") in
            List.iter
              (fun (sx, sy) ->
                let seen = Camera.ray_into c sx sy o d in
                let r = Camera.ray c sx sy in
                if seen <> Camera.sees c sx sy then Alcotest.failf "%s: sees differs" kind;
                if Vec3.dist (Vec3.of_m o) r.origin > 1e-12 || Vec3.dist (Vec3.of_m d) r.dir > 1e-12 then
                  Alcotest.failf "%s: differs at %g %g" kind sx sy;
                if Float.abs (Vec3.length r.dir -. 1.) > 1e-12 then Alcotest.failf "%s: not a unit" kind)
              [ (0., 0.); (0.4, -0.3); (-0.5, 0.5); (0.1, 0.45) ])
          [
            "perspective"; "orthographic"; "cylinder 1 angle 200"; "cylinder 2"; "cylinder 3 angle 200";
            "cylinder 4"; "fisheye angle 270"; "omnimax"; "ultra_wide_angle angle 200"; "panoramic";
            "spherical angle 300, 120";
          ]);
    Alcotest.test_case "depth of field: lens radius aperture/4, rays meet on the focal plane" `Quick
      (fun () ->
        let c = cam "camera { location <0,0,-5> look_at 0 aperture 1 focal_point <0,0,0> blur_samples 16 }" in
        Alcotest.(check (float 1e-9)) "focal distance" 5. c.focal_distance;
        let pin = Camera.ray c 0.1 0.2 in
        let focus = Ray.at pin (5. /. pin.dir.z) in
        List.iter
          (fun (u, v) ->
            let r = Camera.ray_lens c 0.1 0.2 u v in
            let off = Vec3.dist r.origin c.location in
            if off > 0.25 +. 1e-12 then Alcotest.failf "lens offset %g > aperture/4" off;
            let p = Ray.at r ((focus.z -. r.origin.z) /. r.dir.z) in
            if Vec3.dist p focus > 1e-9 then Alcotest.fail "not on the focal point")
          [ (0., 0.); (0.999999, 0.3); (0.5, 0.7); (0.25, 0.1) ];
        let edge = Camera.ray_lens c 0. 0. 1. 0. in
        Alcotest.(check (float 1e-9)) "edge" 0.25 (Vec3.dist edge.origin c.location));
    Alcotest.test_case "an aperture without blur_samples: no focal blur (POV-Ray), with a warning" `Quick
      (fun () ->
        let c, w =
          Camlray_lang.Diag.collect_warnings (fun () ->
              cam "camera { location <0,0,-5> look_at 0 aperture 1 focal_point <0,0,0> }")
        in
        Alcotest.(check (float 0.)) "aperture" 0. c.aperture;
        if not (Helpers.contains w "no blur_samples") then Alcotest.failf "warning: %S" w;
        let c = cam "camera { aperture 1 blur_samples 4, 32 }" in
        Alcotest.(check (pair int int)) "blur_samples 4, 32" (4, 32) (c.blur_samples_min, c.blur_samples));
  ]

(* POV-Ray's confidence test for focal blur *)
let confidence =
  [
    Alcotest.test_case "chi-square quantiles: the tables' values" `Quick (fun () ->
        (* x with P(X > x) = p, from the usual tables (5 significant digits) *)
        List.iter
          (fun (df, p, x) ->
            let q = Chi2.quantile_upper ~df p in
            if Float.abs (q -. x) > 5e-5 *. x then Alcotest.failf "df %g, p %g: %g, table %g" df p q x)
          [ (1., 0.9, 0.015791); (2., 0.9, 0.21072); (5., 0.9, 1.6103); (10., 0.9, 4.8652);
            (30., 0.9, 20.599); (100., 0.9, 82.358); (1., 0.05, 3.8415); (10., 0.05, 18.307);
            (100., 0.05, 124.34); (4., 0.5, 3.3567) ]);
    Alcotest.test_case "chi-square: quantile and tail are inverses" `Quick (fun () ->
        List.iter
          (fun df ->
            List.iter
              (fun p ->
                let x = Chi2.quantile_upper ~df p in
                Alcotest.(check (float 1e-12)) "tail" p (Chi2.upper_tail ~df x))
              [ 0.01; 0.1; 0.5; 0.9; 0.99 ])
          [ 0.5; 1.; 3.; 17.; 63.; 500. ]);
    Alcotest.test_case "thresholds: variance x q(n) / q(N - 1), rising to about the variance" `Quick
      (fun () ->
        let c = cam "camera { aperture 1 blur_samples 64 confidence 0.95 variance 0.01 }" in
        let t = c.blur_thresholds in
        Alcotest.(check int) "one a count" 64 (Array.length t);
        let q d = Chi2.quantile_upper ~df:d 0.95 in
        Alcotest.(check (float 1e-15)) "n = 7" (0.01 *. q 7. /. q 63.) t.(6);
        Alcotest.(check (float 1e-15)) "n = 63" 0.01 t.(62);
        Array.iteri (fun i x -> if i > 0 && x <= t.(i - 1) then Alcotest.fail "not rising") t;
        (* the defaults: 0.9 and 1/128 *)
        let d = cam "camera { aperture 1 blur_samples 10 }" in
        Alcotest.(check (float 1e-15)) "defaults" (1. /. 128.) d.blur_thresholds.(8));
    Alcotest.test_case "lens points: the centre, a hexagon, then every prefix spread over the disc" `Quick
      (fun () ->
        let n = 200 in
        let p = Camera.blur_points n in
        Alcotest.(check (pair (float 0.) (float 0.))) "centre" (0., 0.) (p.(0), p.(1));
        for i = 1 to 6 do
          Alcotest.(check (float 1e-12)) "hexagon" 0.95 (Float.hypot p.(2 * i) p.((2 * i) + 1))
        done;
        for i = 0 to n - 1 do
          if Float.hypot p.(2 * i) p.((2 * i) + 1) > 1. then Alcotest.failf "point %d outside the disc" i
        done;
        (* the largest gap: no point of the disc (a fine grid of them) is
           farther than 2.1 / sqrt k from the first k points (1.1 / sqrt k
           is a hexagonal lattice's); k random points leave gaps of 2.9 to
           4 / sqrt k *)
        List.iter
          (fun k ->
            let gap = ref 0. in
            for gx = -40 to 40 do
              for gy = -40 to 40 do
                let x = float_of_int gx /. 40. and y = float_of_int gy /. 40. in
                if Float.hypot x y <= 1. then begin
                  let d = ref infinity in
                  for j = 0 to k - 1 do
                    d := Float.min !d (Float.hypot (x -. p.(2 * j)) (y -. p.((2 * j) + 1)))
                  done;
                  gap := Float.max !gap !d
                end
              done
            done;
            if !gap > 2.1 /. Float.sqrt (float_of_int k) then
              Alcotest.failf "the first %d points leave a gap of %g (at most %g)" k !gap
                (2.1 /. Float.sqrt (float_of_int k)))
          [ 7; 10; 13; 19; 25; 37; 64; 100; 200 ]);
  ]

let tests = ("camera", units @ confidence)

