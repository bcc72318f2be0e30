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
            (* two nearby rays hitting the same part: the chord is tangent.
               A chord under 1e-6 is left out: the rays' offset is 1e-5 of
               the hit's distance, and a hit very near the origin (an
               isosurface at t = 0.0027, seed 64489184) gives a chord of
               3e-8, where an isosurface's 1e-9 root accuracy tilts it by
               5 degrees *)
            let ok = ref true in
            List.iter
              (fun e ->
                let r' = Ray.make r.origin (Vec3.madd r.dir 1e-5 e) in
                match hit_of s xf r' with
                | Some (_, h', p', _) when h'.id = h.id ->
                    let d = Vec3.sub p' p in
                    let l = Vec3.length d in
                    if l > 1e-6 && l < 1e-3 && Float.abs (Vec3.dot d n) > 2e-2 *. l then ok := false
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
    QCheck.Test.make ~name:"algebraic: the normal points where the polynomial grows" ~count:2000
      (QCheck.make ~print QCheck.Gen.(triple galgebraic gxform gray))
      (fun (s, xf, r) ->
        match (s, hit_of s xf r) with
        | Shape.Algebraic a, Some (_, _, p, n) ->
            let value w = let q = Transform.inv_point xf w in Algebraic.eval a q.x q.y q.z in
            value (Vec3.madd p 1e-5 n) > value (Vec3.madd p (-1e-5) n)
        | _ -> true);
    QCheck.Test.make ~name:"algebraic: a torus as a quartic is hit where the torus is" ~count:3000
      (QCheck.make ~print:(fun ((r1, r2), xf, (r : Ray.t)) ->
           Printf.sprintf "%g %g %s ray %s -> %s" r1 r2 (Transform.to_string xf) (Vec3.to_string r.origin)
             (Vec3.to_string r.dir))
         QCheck.Gen.(triple (pair (fr 0.5 1.5) (fr 0.1 0.5)) gxform gray))
      (fun ((r1, r2), xf, r) ->
        let t s = Object.intersect (Object.make ~xform:xf s) r 1e-9 infinity in
        let a = t (Shape.torus r1 r2) and b = t (Shape.Algebraic (torus_quartic r1 r2)) in
        if a = infinity && b = infinity then true
        else if Float.abs (a -. b) <= 1e-7 *. Float.max 1. a then true
        else QCheck.Test.fail_reportf "torus %g, quartic %g" a b);
    QCheck.Test.make ~name:"algebraic: an ellipsoid as a quadric is hit where the scaled sphere is" ~count:3000
      (QCheck.make ~print:(fun ((a, b, c), (r : Ray.t)) ->
           Printf.sprintf "%g %g %g ray %s -> %s" a b c (Vec3.to_string r.origin) (Vec3.to_string r.dir))
         QCheck.Gen.(pair (triple (fr 0.3 1.5) (fr 0.3 1.5) (fr 0.3 1.5)) gray))
      (fun ((a, b, c), r) ->
        let sphere = Object.make ~xform:(Transform.scale (v a b c)) (Shape.sphere Vec3.zero 1.) in
        let t o = Object.intersect o r 1e-9 infinity in
        let x = t sphere and y = t (Object.make (Shape.Algebraic (quadric a b c (-1.)))) in
        if x = infinity && y = infinity then true
        else if Float.abs (x -. y) <= 1e-7 *. Float.max 1. x then true
        else QCheck.Test.fail_reportf "sphere %g, quadric %g" x y);
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

let algebraic_units =
  [
    Alcotest.test_case "quartic: term k of POV-Ray's table is its monomial" `Quick (fun () ->
        List.iteri
          (fun k name ->
            let i, j, l = powers name in
            let a = Algebraic.make 4 (Array.init 35 (fun m -> if m = k then 1. else 0.)) in
            Alcotest.(check (float 0.)) name (2. ** float i *. (3. ** float j) *. (5. ** float l))
              (Algebraic.eval a 2. 3. 5.))
          quartic_terms);
    Alcotest.test_case "quadric inside: POV-Ray's <= 0, poly's < 1e-4" `Quick (fun () ->
        let unit_sphere below = Algebraic.make ~inside_below:below 2 [| 1.; 0.; 0.; 0.; 1.; 0.; 0.; 1.; 0.; -1. |] in
        Alcotest.(check bool) "poly: just outside counts" true (Algebraic.inside (unit_sphere 1e-4) 1.00001 0. 0.);
        Alcotest.(check bool) "quadric: on the surface" true
          (Algebraic.inside (unit_sphere (Float.succ 0.)) 1. 0. 0.);
        Alcotest.(check bool) "quadric: just outside" false
          (Algebraic.inside (unit_sphere (Float.succ 0.)) 1.00001 0. 0.));
    Alcotest.test_case "a ray along which the quartic drops to a quadratic" `Quick (fun () ->
        (* x^4 + y^2 + z^2 - 1: along z, only z^2 - 1 is left *)
        let a = Algebraic.make 4 (quartic [ ((4, 0, 0), 1.); ((0, 2, 0), 1.); ((0, 0, 2), 1.); ((0, 0, 0), -1.) ]) in
        Alcotest.(check (float 1e-12)) "distance" 4. (Algebraic.first_hit a 0. 0. (-5.) 0. 0. 1. 0.));
  ]

(* Blobs: one component of strength 1 and radius 1 at threshold 1/4
   meets (1 - d^2)^2 = 1/4 at d = sqrt(1/2), from its centre or from its
   segment (round ends); two components add. *)
let blob_units =
  let r = Float.sqrt 0.5 in
  let hit b o d = Shape.intersect (Shape.Blob b) (Ray.make o d) 1e-9 infinity in
  [
    Alcotest.test_case "blob: one sphere's surface at sqrt(1/2)" `Quick (fun () ->
        let b = Blob.make ~threshold:0.25 [ Blob.Sphere { center = Vec3.zero; radius = 1.; strength = 1. } ] in
        Alcotest.(check (float 1e-12)) "from the front" (5. -. r) (hit b (v 0. 0. (-5.)) z);
        Alcotest.(check (float 1e-12)) "from inside" r (hit b Vec3.zero x));
    Alcotest.test_case "blob: a cylinder's side and round end" `Quick (fun () ->
        let b =
          Blob.make ~threshold:0.25
            [ Blob.Cylinder { a = v (-1.) 0. 0.; b = v 1. 0. 0.; radius = 1.; strength = 1. } ]
        in
        Alcotest.(check (float 1e-12)) "side" (5. -. r) (hit b (v 0.3 0. (-5.)) z);
        Alcotest.(check (float 1e-12)) "end" (4. -. r) (hit b (v (-5.) 0. 0.) x);
        (* 0.3 off the axis: the round end at d^2 = (x + 1)^2 + 0.09 = 1/2 *)
        Alcotest.(check (float 1e-12)) "off-axis end" (4. -. Float.sqrt 0.41) (hit b (v (-5.) 0.3 0.) x));
    Alcotest.test_case "blob: fields add, a negative strength subtracts" `Quick (fun () ->
        let s c k = Blob.Sphere { center = c; radius = 1.; strength = k } in
        let b = Blob.make ~threshold:0.6 [ s (v (-0.5) 0. 0.) 1.; s (v 0.5 0. 0.) 1. ] in
        (* at the midpoint each adds (1 - 1/4)^2 *)
        Alcotest.(check (float 1e-15)) "sum" (2. *. 0.5625) (Blob.field b 0. 0. 0.);
        Alcotest.(check bool) "inside where the sum passes" true (Blob.inside b 0. 0. 0.);
        let c = Blob.make ~threshold:0.6 [ s (v (-0.5) 0. 0.) 1.; s (v 0.5 0. 0.) (-1.) ] in
        Alcotest.(check (float 1e-15)) "cancelled" 0. (Blob.field c 0. 0. 0.));
  ]

(* Prisms: a square swept along y is the box; for every spline and sweep
   a hit's normal leaves the solid one way and enters it the other (the
   inside test counts the curves' crossings: it and the hits agree). *)
let arrow = [| (0.2, -1.0); (0.2, 0.2); (1.0, -0.2); (1.0, 0.2); (0.2, 1.0); (-0.2, 1.0); (-1.0, 0.2); (-1.0, -0.2);
               (-0.2, 0.2); (-0.2, -1.0); (0.2, -1.0) |]

let prism_of spline sweep pts =
  match Prism.make spline sweep 0.5 1.0 pts with Ok p -> p | Error e -> Alcotest.fail e

let prism_units =
  [
    (* a Catmull-Rom segment between equal points z = -1 has z(s) = 0.6 s^2
       - 0.6 s - 1 up to a leading coefficient left over from rounding; its
       extreme -1.15 (at s = 0.5) must be found whatever that coefficient *)
    Alcotest.test_case "prism: a cubic's extent with a vanishing leading coefficient" `Quick (fun () ->
        List.iter
          (fun a ->
            let lo, hi = Prism.extent a 0.6 (-0.6) (-1.) in
            Alcotest.(check (float 1e-9)) (Printf.sprintf "low, a = %g" a) (-1.15) lo;
            Alcotest.(check (float 1e-9)) (Printf.sprintf "high, a = %g" a) (-1.) hi)
          [ 0.; 2.8e-17; -2.8e-17; 1e-12 ]);
    Alcotest.test_case "prism: a square swept is the box" `Quick (fun () ->
        let sq = [| (-1., -1.); (1., -1.); (1., 1.); (-1., 1.); (-1., -1.) |] in
        let p = Shape.Prism (prism_of Prism.Linear Prism.Linear_sweep sq) in
        let b = Shape.box (v (-1.) 0.5 (-1.)) (v 1. 1. 1.) in
        let st = Random.State.make [| 5 |] in
        for _ = 1 to 2000 do
          let o = v (Random.State.float st 10. -. 5.) (Random.State.float st 10. -. 5.) (Random.State.float st 10. -. 5.) in
          let r = Ray.make o (Vec3.sub (v (Random.State.float st 2. -. 1.) 0.75 (Random.State.float st 2. -. 1.)) o) in
          let a = Shape.intersect p r 1e-9 infinity and c = Shape.intersect b r 1e-9 infinity in
          if not ((a = infinity && c = infinity) || Float.abs (a -. c) <= 1e-12) then
            Alcotest.failf "prism %g, box %g from %s" a c (Vec3.to_string o)
        done);
    Alcotest.test_case "prism: too few points, a curve left open" `Quick (fun () ->
        let bad r = match r with Error _ -> () | Ok _ -> Alcotest.fail "accepted" in
        bad (Prism.make Prism.Linear Prism.Linear_sweep 0. 1. [| (0., 0.); (1., 0.) |]);
        bad (Prism.make Prism.Cubic Prism.Linear_sweep 0. 1. (Array.sub arrow 0 5)));
  ]

(* the prisms the properties draw: spline [k] (linear, quadratic,
   cubic) on the arrow, swept straight or to a point; and rays towards
   points of its height range [lo, hi] *)
let prism_case k conic =
  let spline, pts =
    match k with
    | 0 -> (Prism.Linear, arrow)
    | 1 -> (Prism.Quadratic, Array.append arrow [| (0.2, 0.2) |])
    | _ -> (Prism.Cubic, Array.concat [ [| (-0.2, -1.0) |]; arrow; [| (0.2, 0.2) |] ])
  in
  prism_of spline (if conic then Prism.Conic_sweep else Prism.Linear_sweep) pts

let prism_rays lo hi =
  QCheck.(make ~print:(fun ((k, c), (r : Ray.t)) -> Printf.sprintf "kind %d conic %b ray %s -> %s" k c
                          (Vec3.to_string r.origin) (Vec3.to_string r.dir))
            Gen.(pair (pair (int_bound 2) bool)
                   (map2 (fun o t -> Ray.make o (Vec3.sub t o)) (gvec 5.)
                      (map3 Vec3.make (fr (-1.) 1.) (fr lo hi) (fr (-1.) 1.)))))

let prism_prop =
  QCheck.Test.make ~name:"prism: normals leave the solid, for every spline and sweep" ~count:2000
    (prism_rays 0.5 1.)
    (fun ((k, conic), r) ->
      let p = prism_case k conic in
      let s = Shape.Prism p in
      let h = Hit.create infinity in
      if not (Shape.hit s r 1e-9 h) then true
      else begin
        let pt = Ray.at r h.t in
        let n = Shape.normal s pt h in
        let a = Vec3.madd pt 1e-6 n and b = Vec3.madd pt (-1e-6) n in
        let ok = (not (Prism.inside p a.x a.y a.z)) && Prism.inside p b.x b.y b.z in
        ok || Float.abs (Vec3.dot n (Vec3.normalize r.dir)) < 1e-3
        || QCheck.Test.fail_reportf "at %s (id %g) normal %s" (Vec3.to_string pt) h.id (Vec3.to_string n)
      end)

(* A prism skips the segments its query's range keeps the ray away
   from: each crossing (the first few along a ray) is found again, the
   same, by a query whose range only just holds it *)
let prism_window_prop =
  QCheck.Test.make ~name:"prism: a crossing is found again in a range that only just holds it" ~count:2000
    (prism_rays 0.4 1.1)
    (fun ((k, conic), r) ->
      let s = Shape.Prism (prism_case k conic) in
      let rec walk tmin n =
        let h = Hit.create infinity in
        n = 0 || (not (Shape.hit s r tmin h))
        || begin
          let w = Hit.create (h.t *. (1. +. 1e-9)) in
          (Shape.hit s r (h.t *. (1. -. 1e-9)) w && w.t = h.t && w.id = h.id
          || QCheck.Test.fail_reportf "crossing %.17g (id %g), in its range %.17g (id %g)" h.t h.id w.t w.id)
          && walk h.t (n - 1)
        end
      in
      walk 1e-9 4)

(* Lathes: a straight profile at radius 1 is an open cylinder; a closed
   profile's normals leave the solid *)
let lathe_units =
  [
    Alcotest.test_case "lathe: a vertical line turned is the open cylinder" `Quick (fun () ->
        let l = match Lathe.make Prism.Linear [| (1., 0.); (1., 2.) |] with Ok l -> l | Error e -> Alcotest.fail e in
        let c = Shape.cylinder ~open_:true Vec3.zero (v 0. 2. 0.) 1. in
        let st = Random.State.make [| 9 |] in
        for _ = 1 to 2000 do
          let o = v (Random.State.float st 8. -. 4.) (Random.State.float st 8. -. 4.) (Random.State.float st 8. -. 4.) in
          let r = Ray.make o (Vec3.sub (v (Random.State.float st 2. -. 1.) (Random.State.float st 2.) (Random.State.float st 2. -. 1.)) o) in
          let a = Shape.intersect (Shape.Lathe l) r 1e-9 infinity and b = Shape.intersect c r 1e-9 infinity in
          if not ((a = infinity && b = infinity) || Float.abs (a -. b) <= 1e-9 *. (1. +. b)) then
            Alcotest.failf "lathe %g, cylinder %g from %s" a b (Vec3.to_string o)
        done);
  ]

let lathe_prop =
  let ring = [| (1.5, 0.); (2., 0.5); (1.5, 1.); (1., 0.5); (1.5, 0.); (2., 0.5); (1.5, 1.) |] in
  QCheck.Test.make ~name:"lathe: normals leave the solid (quadratic and cubic rings)" ~count:2000
    QCheck.(make ~print:(fun (c, (r : Ray.t)) -> Printf.sprintf "cubic %b ray %s -> %s" c (Vec3.to_string r.origin) (Vec3.to_string r.dir))
              Gen.(pair bool (map2 (fun o t -> Ray.make o (Vec3.sub t o)) (gvec 5.) (map3 Vec3.make (fr (-2.) 2.) (fr 0. 1.) (fr (-2.) 2.)))))
    (fun (cubic, r) ->
      let l =
        match Lathe.make (if cubic then Prism.Cubic else Prism.Quadratic) (if cubic then ring else Array.sub ring 0 6) with
        | Ok l -> l
        | Error e -> failwith e
      in
      let s = Shape.Lathe l in
      let h = Hit.create infinity in
      (* known limit: a ray within 1e-4 of level (|dy| / |d|) meets a
         double root of the height equation, found to some 1e-3 only
         (found: dy / |d| = 1.8e-6); exactly level rays take their own
         exact path *)
      if Float.abs r.dir.y < 1e-4 *. Vec3.length r.dir && r.dir.y <> 0. then true
      else if not (Shape.hit s r 1e-9 h) then true
      else begin
        let pt = Ray.at r h.t in
        let n = Shape.normal s pt h in
        let a = Vec3.madd pt 1e-6 n and b = Vec3.madd pt (-1e-6) n in
        ((not (Lathe.inside l a.x a.y a.z)) && Lathe.inside l b.x b.y b.z)
        || Float.abs (Vec3.dot n (Vec3.normalize r.dir)) < 1e-3
        || QCheck.Test.fail_reportf "at %s normal %s" (Vec3.to_string pt) (Vec3.to_string n)
      end)

(* Superellipsoids: <1, 1> is the unit sphere (POV-Ray's tolerance on
   the function, 1e-10, within 1e-8 in distance); normals leave the solid *)
let superellipsoid_units =
  [
    Alcotest.test_case "superellipsoid <1, 1> is the unit sphere" `Quick (fun () ->
        let se = Shape.Superellipsoid (Superellipsoid.make 1. 1.) and sp = Shape.sphere Vec3.zero 1. in
        let st = Random.State.make [| 11 |] in
        for _ = 1 to 2000 do
          let o = v (Random.State.float st 8. -. 4.) (Random.State.float st 8. -. 4.) (Random.State.float st 8. -. 4.) in
          let r = Ray.make o (Vec3.sub (v (Random.State.float st 1.6 -. 0.8) (Random.State.float st 1.6 -. 0.8)
                                          (Random.State.float st 1.6 -. 0.8)) o) in
          let a = Shape.intersect se r 1e-9 infinity and b = Shape.intersect sp r 1e-9 infinity in
          if not ((a = infinity && b = infinity) || Float.abs (a -. b) <= 1e-8 *. (1. +. b)) then
            Alcotest.failf "superellipsoid %g, sphere %g from %s" a b (Vec3.to_string o)
        done);
  ]

let superellipsoid_prop =
  QCheck.Test.make ~name:"superellipsoid: normals leave the solid" ~count:2000
    QCheck.(make ~print:(fun ((e, n), (r : Ray.t)) -> Printf.sprintf "<%g, %g> ray %s -> %s" e n
                            (Vec3.to_string r.origin) (Vec3.to_string r.dir))
              Gen.(pair (pair (fr 0.2 2.5) (fr 0.2 2.5)) (map2 (fun o t -> Ray.make o (Vec3.sub t o)) (gvec 5.) (gvec 0.9))))
    (fun ((e, n), r) ->
      let t = Superellipsoid.make e n in
      let s = Shape.Superellipsoid t in
      let h = Hit.create infinity in
      if not (Shape.hit s r 1e-9 h) then true
      else begin
        let pt = Ray.at r h.t in
        let nn = Shape.normal s pt h in
        let a = Vec3.madd pt 1e-5 nn and b = Vec3.madd pt (-1e-5) nn in
        ((not (Superellipsoid.inside t a.x a.y a.z)) && Superellipsoid.inside t b.x b.y b.z)
        || Float.abs (Vec3.dot nn (Vec3.normalize r.dir)) < 1e-2
        (* within 1e-4 of a coordinate plane an exponent above 2 makes a
           crease, where the normal turns through a right angle over a
           distance shorter than the step (found: z = 1.8e-6, n = 2.19) *)
        || ((e > 2. || n > 2.) && Float.min (Float.abs pt.x) (Float.min (Float.abs pt.y) (Float.abs pt.z)) < 1e-4)
        || QCheck.Test.fail_reportf "at %s normal %s" (Vec3.to_string pt) (Vec3.to_string nn)
      end)

(* Roots of polynomials made from their roots: the first above [lo] *)
let roots_prop =
  QCheck.Test.make ~name:"Poly.first_root: the first root above lo of a product of (t - r_i)" ~count:3000
    QCheck.(make ~print:(fun (rs, (k, lo)) ->
                Printf.sprintf "roots [%s] scale %g lo %g" (String.concat "; " (List.map string_of_float rs)) k lo)
              Gen.(pair (list_size (int_range 1 6) (fr (-5.) 5.)) (pair (fr (-3.) 3.) (fr (-6.) 6.))))
    (fun (rs, (k, lo)) ->
      QCheck.assume (Float.abs k > 0.01);
      (* roots closer than 1e-3 make a near-double root: found or not *)
      let sorted = List.sort compare rs in
      let rec spaced = function a :: (b :: _ as r) -> b -. a > 1e-3 && spaced r | _ -> true in
      QCheck.assume (spaced sorted && List.for_all (fun r -> Float.abs (r -. lo) > 1e-6) rs);
      let c = List.fold_left (fun c r ->
        (* c * (t - r) *)
        let n = Array.length c in
        Array.init (n + 1) (fun m -> (if m > 0 then c.(m - 1) else 0.) -. (if m < n then r *. c.(m) else 0.)))
        [| k |] rs in
      let degree = List.length rs in
      let sc = Poly.scratch 8 in
      let got =
        if Poly.first_root sc (Float.Array.init (degree + 1) (fun m -> c.(m))) degree lo then Poly.root sc
        else infinity
      in
      let want = List.fold_left (fun a r -> if r > lo && r < a then r else a) infinity sorted in
      if want = infinity then got = infinity
      else if Float.abs (got -. want) <= 1e-8 *. (1. +. Float.abs want) then true
      else QCheck.Test.fail_reportf "got %.17g, want %.17g" got want)

(* Poly.cubic_roots_in, which prisms use, against the general search it
   stands for (Prism.all_roots, over Poly.first_root_in): the same roots
   in [0, 1); to the bit for a quadratic or a line, also one under a
   leading term both drop (1e-25 of the next); a leading term of 1e-17
   (rounding left over) makes a cubic, whose critical points differ *)
let cubic_roots_prop =
  QCheck.Test.make ~name:"Poly.cubic_roots_in: the roots Prism.all_roots finds" ~count:3000
    QCheck.(make ~print:(fun (rs, (k, (tiny, wide))) ->
                Printf.sprintf "roots [%s] scale %g leading %g wide %b"
                  (String.concat "; " (List.map string_of_float rs)) k tiny wide)
              Gen.(pair (list_size (int_range 1 3) (fr (-0.5) 1.5))
                     (pair (fr (-3.) 3.) (pair (oneof_list [ 0.; 1e-25; 1e-17 ]) bool))))
    (fun (rs, (k, (tiny, wide))) ->
      QCheck.assume (Float.abs k > 0.01);
      (* roots off the ends by more than the searches' steps, and apart
         (roots close together are known only roughly: the polynomial is
         flat there) *)
      let sorted = List.sort compare rs and hi = if wide then 1. +. 1e-12 else 1. in
      let rec spaced = function a :: (b :: _ as r) -> b -. a > 1e-3 && spaced r | _ -> true in
      QCheck.assume (spaced sorted && List.for_all (fun r -> Float.abs r > 1e-9 && Float.abs (r -. hi) > 1e-9) rs);
      let c = List.fold_left (fun c r ->
        let n = Array.length c in
        Array.init (n + 1) (fun m -> (if m > 0 then c.(m - 1) else 0.) -. (if m < n then r *. c.(m) else 0.)))
        [| k |] rs in
      let coef m = if m < Array.length c then c.(m) else if m = 3 then tiny *. k else 0. in
      let degree = List.length rs in
      let want = Float.Array.make 3 0. and got = Float.Array.make 3 0. in
      let nw = Prism.all_roots (Poly.scratch 3) (Float.Array.init 4 coef) 3 want 0. hi in
      let ng = Poly.cubic_roots_in got (coef 3) (coef 2) (coef 1) (coef 0) 0. hi in
      let same i =
        let a = Float.Array.get want i and b = Float.Array.get got i in
        if degree < 3 && tiny < 1e-20 then a = b else Float.abs (a -. b) <= 1e-10 *. (1. +. Float.abs a)
      in
      (nw = ng && List.for_all same (List.init nw Fun.id))
      || QCheck.Test.fail_reportf "all_roots: %s; cubic_roots_in: %s"
           (String.concat " " (List.init nw (fun i -> Printf.sprintf "%.17g" (Float.Array.get want i))))
           (String.concat " " (List.init ng (fun i -> Printf.sprintf "%.17g" (Float.Array.get got i)))))

let folded =
  Alcotest.test_case "a sphere under a similarity is stored moved" `Quick (fun () ->
      let xf = Transform.then_ (Transform.then_ (Transform.scale (v 2. 2. 2.)) (Transform.rotate (v 10. 20. 30.)))
          (Transform.translate (v 3. 0. 0.)) in
      let o = Object.make ~xform:xf (Shape.sphere Vec3.zero 1.) in
      Alcotest.(check bool) "identity transform" true (Transform.is_identity o.xform);
      Alcotest.(check (float 1e-12)) "distance" 8. (Object.intersect o (Ray.make (v 3. 0. (-10.)) z) 0. infinity);
      let o' = Object.make ~xform:(Transform.scale (v 2. 1. 1.)) (Shape.sphere Vec3.zero 1.) in
      Alcotest.(check bool) "an ellipsoid keeps its transform" false (Transform.is_identity o'.xform))

(* polygon: even-odd over every outline, errors for bad point sets *)
let polygon_units =
  let pts l = Array.of_list (List.map (fun (a, b) -> v a b 0.) l) in
  let square_with_hole =
    pts [ (0., 0.); (4., 0.); (4., 4.); (0., 4.); (0., 0.); (1., 1.); (3., 1.); (3., 3.); (1., 3.); (1., 1.) ]
  in
  let hits p x y =
    Shape.intersect (Shape.Polygon p) (Ray.make (v x y (-1.)) Vec3.unit_z) 0. infinity < infinity
  in
  [
    Alcotest.test_case "polygon: the ring is hit, the hole and the outside are not" `Quick (fun () ->
        match Polygon.make square_with_hole with
        | Error e -> Alcotest.fail e
        | Ok (p, closed) ->
            Alcotest.(check bool) "closed" true closed;
            Alcotest.(check bool) "ring" true (hits p 0.5 2.);
            Alcotest.(check bool) "hole" false (hits p 2. 2.);
            Alcotest.(check bool) "outside" false (hits p 5. 2.);
            Alcotest.(check (float 1e-12)) "at z = 0" 1.
              (Shape.intersect (Shape.Polygon p) (Ray.make (v 0.5 2. (-1.)) Vec3.unit_z) 0. infinity));
    Alcotest.test_case "polygon: an open outline is closed; bad point sets are errors" `Quick (fun () ->
        (match Polygon.make (pts [ (0., 0.); (2., 0.); (0., 2.) ]) with
        | Ok (p, closed) ->
            Alcotest.(check bool) "reported open" false closed;
            Alcotest.(check bool) "closed here" true (hits p 0.5 0.5);
            Alcotest.(check bool) "past the closing edge" false (hits p 1.5 1.5)
        | Error e -> Alcotest.fail e);
        let bad l = match Polygon.make l with Ok _ -> false | Error _ -> true in
        Alcotest.(check bool) "two points" true (bad (pts [ (0., 0.); (1., 0.) ]));
        Alcotest.(check bool) "on one line" true (bad (pts [ (0., 0.); (1., 0.); (2., 0.); (0., 0.) ]));
        Alcotest.(check bool) "not flat" true
          (bad [| v 0. 0. 0.; v 1. 0. 0.; v 1. 1. 0.; v 0. 1. 0.5; v 0. 0. 0. |]));
  ]

(* height_field: known answers, POV-Ray's pixel mapping and diagonal (as
   povray's trace() gave them), water level, smooth normals, the parser *)
let hf_units =
  let mk ?(smooth = false) ?(water = 0.) w d hs = Height_field.make ~width:w ~depth:d ~heights:(Array.of_list hs) ~smooth ~water in
  let down_at f px pz =
    let h = Hit.create infinity in
    let r = Ray.make (v px 2. pz) down in
    if Shape.hit (Shape.Height_field f) r 0. h then Some (h.t, Shape.normal (Shape.Height_field f) (Ray.at r h.t) h)
    else None
  in
  let surface_y f px pz = match down_at f px pz with Some (t, _) -> 2. -. t | None -> nan in
  let write_file name contents =
    (* in the working folder (scenes may read there), removed when the
       tests end *)
    let p = Filename.concat (Sys.getcwd ()) (Printf.sprintf "%d-%s" (Unix.getpid ()) name) in
    at_exit (fun () -> try Sys.remove p with Sys_error _ -> ());
    Out_channel.with_open_bin p (fun oc -> output_string oc contents);
    p
  in
  let parsed_field src =
    let sdl = match Camlray_lang.Parse.string src with Ok s -> s | Error d -> Alcotest.fail (Camlray_lang.Diag.to_string d) in
    match sdl.Camlray_lang.Sdl.items with
    | [ Camlray_lang.Sdl.Object { shape = Camlray_lang.Sdl.Height_field hf; _ } ] -> (sdl, hf.field)
    | _ -> Alcotest.fail "not one height field"
  in
  [
    Alcotest.test_case "height_field: a flat field is hit where its plane is, normal up" `Quick (fun () ->
        let f = mk 3 4 (List.init 12 (fun _ -> 32768)) in
        match down_at f 0.3 0.7 with
        | Some (t, n) ->
            Alcotest.(check (float 1e-12)) "t" 1.5 t;
            Alcotest.(check bool) "normal +y" true (vclose n y)
        | None -> Alcotest.fail "no hit");
    Alcotest.test_case "height_field: a ramp's height and normal" `Quick (fun () ->
        (* columns 0, 30000, 60000 on both rows: slope 60000/65536 over x *)
        let f = mk 3 2 [ 0; 30000; 60000; 0; 30000; 60000 ] in
        let k = 60000. /. 65536. in
        Alcotest.(check (float 1e-12)) "height at x = 0.25" (0.25 *. k) (surface_y f 0.25 0.4);
        match down_at f 0.8 0.5 with
        | Some (_, n) ->
            let e = Vec3.normalize (v (-.k) 1. 0.) in
            if not (vclose n e) then Alcotest.failf "normal %s, expected %s" (Vec3.to_string n) (Vec3.to_string e)
        | None -> Alcotest.fail "no hit");
    Alcotest.test_case "height_field: the image's top row is z = 1, cells cut from (1,0) to (0,1)" `Quick (fun () ->
        (* 2 x 2: only the bottom-left pixel (image row 1) is high: the corner x = 0, z = 0 *)
        let f = mk 2 2 [ 0; 0; 65535; 0 ] in
        Alcotest.(check (float 1e-9)) "(0.25, 0.25) on the corner's triangle" (65535. *. 0.5 /. 65536.) (surface_y f 0.25 0.25);
        Alcotest.(check (float 1e-9)) "(0.4, 0.4) too" (65535. *. 0.2 /. 65536.) (surface_y f 0.4 0.4);
        Alcotest.(check (float 1e-9)) "(0.6, 0.6) on the other, flat" 0. (surface_y f 0.6 0.6);
        Alcotest.(check (float 1e-9)) "(0.1, 0.8) on the corner's triangle" (65535. *. 0.1 /. 65536.) (surface_y f 0.1 0.8));
    Alcotest.test_case "height_field: water_level cuts the surface below it" `Quick (fun () ->
        let hs = [ 0; 30000; 60000; 0; 30000; 60000 ] in
        let dry = mk 3 2 hs and wet = mk ~water:0.5 3 2 hs in
        Alcotest.(check bool) "low part without water" true (down_at dry 0.1 0.5 <> None);
        Alcotest.(check bool) "low part under water: gone" true (down_at wet 0.1 0.5 = None);
        Alcotest.(check (float 1e-12)) "high part stays" (surface_y dry 0.9 0.5) (surface_y wet 0.9 0.5);
        Alcotest.(check bool) "inside under the water" true (Shape.inside (Shape.Height_field wet) (v 0.1 0.3 0.5));
        Alcotest.(check bool) "inside under the surface" true (Shape.inside (Shape.Height_field dry) (v 0.9 0.5 0.5));
        Alcotest.(check bool) "above is outside" false (Shape.inside (Shape.Height_field dry) (v 0.9 0.95 0.5)));
    Alcotest.test_case "height_field: smooth normals blend the corners' normals" `Quick (fun () ->
        (* flat then rising: the flat cell's smooth normal leans away from the rise *)
        let hs = [ 0; 0; 60000; 0; 0; 60000; 0; 0; 60000 ] in
        let f = mk ~smooth:true 3 3 hs in
        let n_at px = match down_at f px 0.5 with Some (_, n) -> n | None -> Alcotest.fail "no hit" in
        let n0 = n_at 0. and n1 = n_at 0.5 and nq = n_at 0.125 in
        let e = Vec3.normalize (Vec3.add (Vec3.scale 0.75 n0) (Vec3.scale 0.25 n1)) in
        if not (vclose ~eps:1e-9 nq e) then Alcotest.failf "blend %s, expected %s" (Vec3.to_string nq) (Vec3.to_string e);
        Alcotest.(check bool) "leans to -x" true (nq.x < 0.);
        (match down_at (mk 3 3 hs) 0.125 0.5 with
         | Some (_, n) -> Alcotest.(check bool) "the flat triangle's is +y" true (vclose n y)
         | None -> Alcotest.fail "no hit"));
    Alcotest.test_case "height_field: a walk allocates nothing" `Quick (fun () ->
        let f = mk 64 64 (List.init (64 * 64) (fun i -> (i * 7919) land 0xFFFF)) in
        let s = Shape.Height_field f in
        let r = Ray.of_ray (Ray.make (v (-0.5) 1.2 0.1) (Vec3.normalize (v 1. (-0.6) 0.8))) in
        let h = Hit.create infinity in
        ignore (Shape.hit_s s r 0. h);
        let before = Gc.minor_words () in
        for _ = 1 to 1000 do
          h.t <- infinity;
          ignore (Shape.hit_s s r 0. h)
        done;
        Alcotest.(check (float 0.)) "words" 0. (Gc.minor_words () -. before));
    Alcotest.test_case "height_field: files and functions read as POV-Ray reads them (trace() values)" `Quick (fun () ->
        let pgm = write_file "camlray-hf-test.pgm" "P5\n3 2\n255\n\x00\x33\x66\x99\xcc\xff" in
        let _, f = parsed_field (Printf.sprintf "height_field { pgm %S }" pgm) in
        (* povray 3.7: 52428 at (0.5, z = 0) (the bottom row, 204), 13107 at z = 1 (51) *)
        Alcotest.(check (float 1e-6)) "bottom row" (52428. /. 65536.) (surface_y f 0.5 1e-9);
        Alcotest.(check (float 1e-6)) "top row" (13107. /. 65536.) (surface_y f 0.5 (1. -. 1e-9));
        let ppm = write_file "camlray-hf-test.ppm" "P6\n2 2\n255\n\xff\x00\x00\x00\xff\x00\x01\x02\x00\x80\x80\x80" in
        let _, c = parsed_field (Printf.sprintf "height_field { ppm %S }" ppm) in
        (* red the high byte: (r*256 + g)*255 *)
        Alcotest.(check (float 0.)) "red" 65280. (Height_field.height c 0 1);
        Alcotest.(check (float 0.)) "green" 255. (Height_field.height c 1 1);
        Alcotest.(check (float 0.)) "1, 2" 258. (Height_field.height c 0 0);
        Alcotest.(check (float 0.)) "grey 128" 32896. (Height_field.height c 1 0);
        let _, fn = parsed_field "height_field { function 3, 2 { x*0.5 + y*0.25 } }" in
        (* povray: 32767 at (0.5, z = 0) (y = 1), 16383 at z = 1 (y = 0) *)
        Alcotest.(check (float 0.)) "fn at z = 0" 32767. (Height_field.height fn 1 0);
        Alcotest.(check (float 0.)) "fn at z = 1" 16383. (Height_field.height fn 1 1);
        let _, wrap = parsed_field "height_field { function 2, 2 { 1.5 } }" in
        Alcotest.(check (float 0.)) "1.5 wraps to 32766 as in povray" 32766. (Height_field.height wrap 0 0);
        let sdl, _ = parsed_field (Printf.sprintf "height_field { pgm %S smooth water_level 0.25 }" pgm) in
        let text = String.concat "\n" (List.map Camlray_lang.Printer.item sdl.items) in
        let sdl', _ = parsed_field text in
        Alcotest.(check string) "printed back" text (String.concat "\n" (List.map Camlray_lang.Printer.item sdl'.items)));
  ]

(* bicubic_patch: a smooth mesh on the Bezier patch *)
let patch_units =
  let compile src =
    match Camlray_lang.Parse.string src with
    | Error d -> Alcotest.failf "%s" (Camlray_lang.Diag.to_string d)
    | Ok sdl -> (
        match Camlray_lang.Compile.scene sdl with
        | Ok s -> s.objects.(0)
        | Error d -> Alcotest.failf "%s" (Camlray_lang.Diag.to_string d))
  in
  let pts f =
    String.concat ", "
      (List.init 16 (fun k -> let i = k / 4 and j = k mod 4 in
         let x, y, z = f (float j) (float i) in Printf.sprintf "<%g, %g, %g>" x y z))
  in
  let down o x y =
    let r = Ray.make (Vec3.make x y (-10.)) Vec3.unit_z in
    let h = Hit.create infinity and f = Object.found o in
    if Object.hit o r 0. h f then
      let p = Ray.at r h.t in
      Some (p, Object.normal f.leaf p h)
    else None
  in
  [
    Alcotest.test_case "bicubic_patch: a flat patch is its plane" `Quick (fun () ->
        let o = compile (Printf.sprintf "bicubic_patch { type 1 u_steps 2 v_steps 2 %s }" (pts (fun x y -> (x, y, 1.)))) in
        (match down o 1.3 2.1 with
         | Some (p, n) ->
             Alcotest.(check (float 1e-9)) "z" 1. p.z;
             Alcotest.(check (float 1e-9)) "normal along z" 1. (Float.abs n.z)
         | None -> Alcotest.fail "missed");
        Alcotest.(check bool) "outside missed" true (down o 3.2 1. = None));
    Alcotest.test_case "bicubic_patch: its surface, as the Bezier formula gives it" `Quick (fun () ->
        (* heights z = x (3 - x) y (3 - y) / 4 at the control points: at
           u = v = 1/2 the patch is at x = y = 1.5, z = (sum of the
           weights 1/8 3/8 3/8 1/8 times heights) = (3/4 * 2 / 4 ... ) *)
        let h x y = x *. (3. -. x) *. y *. (3. -. y) /. 4. in
        let o = compile (Printf.sprintf "bicubic_patch { u_steps 4 v_steps 4 %s }" (pts (fun x y -> (x, y, h x y)))) in
        let w = [| 0.125; 0.375; 0.375; 0.125 |] in
        let z = ref 0. in
        for i = 0 to 3 do for j = 0 to 3 do z := !z +. (w.(i) *. w.(j) *. h (float j) (float i)) done done;
        match down o 1.5 1.5 with
        | Some (p, n) ->
            (* a vertex of the 16 x 16 grid: exact *)
            Alcotest.(check (float 1e-9)) "centre height" !z p.z;
            (* symmetric: the normal is along z there *)
            Alcotest.(check (float 1e-9)) "centre normal" 1. (Float.abs n.z)
        | None -> Alcotest.fail "missed");
    Alcotest.test_case "bicubic_patch: 16 points, steps 0 to 10" `Quick (fun () ->
        let err src = match Camlray_lang.Parse.string src with
          | Ok _ -> Alcotest.failf "accepted: %s" src | Error d -> d.msg in
        Alcotest.(check string) "15 points" "a bicubic_patch needs 16 control points, found 15"
          (err (Printf.sprintf "bicubic_patch { %s }" (String.concat ", " (List.init 15 (fun i -> Printf.sprintf "<%d,0,0>" i)))));
        Alcotest.(check string) "steps" "u_steps goes from 0 to 10, found 11"
          (err (Printf.sprintf "bicubic_patch { u_steps 11 %s }" (pts (fun x y -> (x, y, 0.))))));
  ]

(* Isosurfaces: known answers. The scene's own shapes come through the
   parser and compiler (the function compiled as scenes compile it). *)
let iso_of src =
  let s = Scn.compile src in
  match s.objects.(0).geom with
  | Object.Prim (Shape.Isosurface i as sh) -> (i, sh)
  | _ -> Alcotest.fail "not an isosurface"

let iso_units =
  let hit sh o d = let h = Hit.create infinity in if Shape.hit sh (Ray.make o d) 1e-9 h then Some h else None in
  [
    Alcotest.test_case "isosurface: x*x+y*y+z*z-r*r is hit where the sphere is, with its normals and inside" `Quick
      (fun () ->
        let i, sh =
          iso_of "isosurface { function { x*x + y*y + z*z - 0.64 } accuracy 1e-7 max_gradient 4 }" in
        let sp = Shape.sphere Vec3.zero 0.8 in
        let rng = Random.State.make [| 7 |] in
        let r () = Random.State.float rng 2. -. 1. in
        let hits = ref 0 in
        for _ = 1 to 2000 do
          let o = Vec3.scale 3. (Vec3.normalize (v (r ()) (r ()) (r ()))) in
          let d = Vec3.normalize (Vec3.sub (v (0.9 *. r ()) (0.9 *. r ()) (0.9 *. r ())) o) in
          match (hit sh o d, hit sp o d) with
          | Some a, Some b ->
              incr hits;
              (* POV-Ray's hit: the end of a stretch no longer than the
                 accuracy, past the crossing *)
              if not (a.t >= b.t -. 1e-9 && a.t <= b.t +. 2e-7) then
                Alcotest.failf "hit at %.9f, the sphere at %.9f" a.t b.t;
              let p = Vec3.madd o a.t d in
              let n = Shape.normal sh p a and ns = Shape.normal sp p b in
              if not (vclose ~eps:1e-5 n ns) then
                Alcotest.failf "normal %s, the sphere's %s" (Vec3.to_string n) (Vec3.to_string ns)
          | None, None -> ()
          | Some a, None -> Alcotest.failf "isosurface hit at %g, the sphere missed" a.t
          | None, Some b ->
              (* only a graze closer than the accuracy may be missed *)
              let p = Vec3.madd o b.t d in
              if Float.abs (Vec3.dot (Shape.normal sp p b) d) > 1e-3 then
                Alcotest.failf "isosurface missed, the sphere hit at %g" b.t
        done;
        if !hits < 500 then Alcotest.failf "only %d hits" !hits;
        for _ = 1 to 2000 do
          let p = v (r ()) (r ()) (r ()) in
          if Float.abs (Vec3.length p -. 0.8) > 1e-6 then
            Alcotest.(check bool) "inside" (Vec3.length p < 0.8) (Isosurface.inside i p.x p.y p.z)
        done);
    Alcotest.test_case "isosurface: threshold moves the surface" `Quick (fun () ->
        let _, sh = iso_of "isosurface { function { sqrt(x*x + y*y + z*z) } threshold 0.5 accuracy 1e-6 }" in
        match hit sh (v 0. 0. (-3.)) z with
        | Some h -> Alcotest.(check (float 2e-6)) "at r = 0.5" 2.5 h.t
        | None -> Alcotest.fail "missed");
    Alcotest.test_case "isosurface: the container shows where the function is inside, unless open" `Quick (fun () ->
        (* f = y: the half-space below y = 0, in the box -1..1 *)
        let i, closed = iso_of "isosurface { function { y } }" in
        let _, opened = iso_of "isosurface { function { y } open }" in
        (match hit closed (v 0. 3. 0.) down with
        | Some h ->
            Alcotest.(check (float 1e-3)) "the surface y = 0 from above" 3. h.t;
            Alcotest.(check bool) "normal +y" true (vclose ~eps:1e-6 (Shape.normal closed (v 0. 0. 0.) h) y)
        | None -> Alcotest.fail "missed from above");
        (match hit closed (v (-3.) (-0.5) 0.) x with
        | Some h ->
            Alcotest.(check (float 1e-12)) "the box face x = -1" 2. h.t;
            Alcotest.(check bool) "normal -x" true
              (vclose (Shape.normal closed (v (-1.) (-0.5) 0.) h) (Vec3.neg x))
        | None -> Alcotest.fail "the container face is not shown");
        Alcotest.(check bool) "open: no container face" true (hit opened (v (-3.) (-0.5) 0.) x = None);
        (match hit opened (v 0. 3. 0.) down with
        | Some h -> Alcotest.(check (float 1e-3)) "open: the surface still" 3. h.t
        | None -> Alcotest.fail "open: missed from above");
        (* from below, inside the function: open looks for where it rises *)
        (match hit opened (v 0. (-3.) 0.) y with
        | Some h -> Alcotest.(check (float 1e-3)) "open from below" 3. h.t
        | None -> Alcotest.fail "open: missed from below");
        (match hit closed (v 0. (-3.) 0.) y with
        | Some h -> Alcotest.(check (float 1e-12)) "closed from below: the box face" 2. h.t
        | None -> Alcotest.fail "closed: missed from below");
        Alcotest.(check bool) "inside below" true (Isosurface.inside i 0.5 (-0.5) 0.5);
        Alcotest.(check bool) "outside above" false (Isosurface.inside i 0.5 0.5 0.5);
        Alcotest.(check bool) "outside the container" false (Isosurface.inside i 0.5 (-0.5) 1.5));
    Alcotest.test_case "isosurface: contained_by sphere" `Quick (fun () ->
        (* a negative radius is its size, as POV-Ray reads it *)
        let _, sh = iso_of "isosurface { function { -1 } contained_by { sphere { <0, 0, 1>, -0.5 } } }" in
        match hit sh (v 0. 0. (-3.)) z with
        | Some h ->
            Alcotest.(check (float 1e-12)) "the sphere" 3.5 h.t;
            (* POV-Ray: the function's gradient, here zero, so +x *)
            Alcotest.(check bool) "the gradient's normal" true (vclose (Shape.normal sh (v 0. 0. 0.5) h) x)
        | None -> Alcotest.fail "missed");
    Alcotest.test_case "isosurface: rays leaving a hit see the far side, not the surface they leave" `Quick
      (fun () ->
        let _, sh = iso_of "isosurface { function { sqrt(x*x + y*y + z*z) - 0.8 } }" in
        let o = v 0.1 0.2 (-3.) in
        match hit sh o z with
        | None -> Alcotest.fail "missed"
        | Some h ->
            let p = Vec3.madd o h.t z in
            let n = Shape.normal sh p h in
            Alcotest.(check bool) "outward: nothing" true (hit sh p n = None);
            (match hit sh p z with
            | Some h' ->
                let q = Vec3.madd p h'.t z in
                (* the far side, within two accuracies of the sphere *)
                Alcotest.(check (float 2e-3)) "through: the far side" 0.8 (Vec3.length q);
                Alcotest.(check bool) "beyond the centre" true (q.z > 0.)
            | None -> Alcotest.fail "through: missed the far side"));
    Alcotest.test_case "isosurface: a hit allocates nothing" `Quick (fun () ->
        let _, sh = iso_of "isosurface { function { sqrt(x*x + y*y + z*z) - 0.9 + 0.1*sin(5*x) } max_gradient 2 }" in
        let r = Ray.scratch () and h = Hit.create infinity in
        Ray.load r (Ray.make (v 0. 0.1 (-3.)) z);
        let go k =
          r.ox <- 0.001 *. float_of_int k;
          h.t <- infinity;
          ignore (Shape.hit_s sh r 1e-9 h)
        in
        go 0;
        let before = Gc.minor_words () in
        for k = 1 to 1000 do go k done;
        let words = Gc.minor_words () -. before in
        if words > 0. then Alcotest.failf "%.0f words for 1000 isosurface hits" words);
  ]

(* sor: the radii, normals, caps and inside test POV-Ray's trace() and
   inside() give for the same profile *)
let julia_units =
  let mk ?(hypercomplex = false) ?(precision = 15.) c cube n =
    match Julia.make ~c ~hypercomplex ~cube ~max_iteration:n ~precision with
    | Ok j -> Shape.Julia j
    | Error e -> Alcotest.fail e
  in
  let c1 = [| -0.083; 0.0; -0.83; -0.025 |] in
  let cross s o d =
    let r = Ray.make o d in
    let h = Hit.create infinity in
    if Shape.hit s r 0. h then let p = Ray.at r h.t in Some (p, Shape.normal s p h) else None
  in
  let check s (o, d, (px, py, pz), (nx, ny, nz)) =
    match cross s o d with
    | Some (p, n) ->
        Alcotest.(check (float 2e-7)) "hit x" px p.x;
        Alcotest.(check (float 2e-7)) "hit y" py p.y;
        Alcotest.(check (float 2e-7)) "hit z" pz p.z;
        Alcotest.(check (float 2e-6)) "normal x" nx n.x;
        Alcotest.(check (float 2e-6)) "normal y" ny n.y;
        Alcotest.(check (float 2e-6)) "normal z" nz n.z
    | None -> Alcotest.fail "missed"
  in
  let v = Vec3.make in
  [
    Alcotest.test_case "julia_fractal: c = 0 (sqr and cube) is the unit ball" `Quick (fun () ->
        List.iter
          (fun cube ->
            let s = mk [| 0.; 0.; 0.; 0. |] cube 8 in
            check s (v 0.3 0.2 (-5.), v 0. 0. 1., (0.3, 0.2, -0.9327379), (0.3, 0.2, -0.9327379));
            Alcotest.(check bool) "inside" true (Shape.inside s (v 0.5 0.5 0.5));
            Alcotest.(check bool) "outside" false (Shape.inside s (v 0.6 0.6 0.6)))
          [ false; true ]);
    Alcotest.test_case "julia_fractal: fractal1's parameters as POV-Ray traces them" `Quick (fun () ->
        (* povray 3.7 trace() on julia_fractal { <-0.083,0,-0.83,-0.025> quaternion sqr|cube max_iteration 8 precision 15 } *)
        let sq = mk c1 false 8 and cu = mk c1 true 8 in
        List.iter (check sq)
          [ (v 0. 0. (-5.), v 0. 0. 1., (0., 0., -0.9754510505), (0.3544145673, 0., -0.9350883993));
            (v 0.3 0.2 (-5.), v 0. 0. 1., (0.3, 0.2, -0.3294082741), (-0.2611676484, 0.3807701202, -0.8870206170));
            (v (-5.) 0.1 0.2, v 1. 0. 0., (-0.3672825323, 0.1, 0.2), (-0.7498815037, -0.0168651354, 0.6613571635));
            (v 0.1 5. 0.2, v 0. (-1.) 0., (0.1, 0.9624901445, 0.2), (-0.0474455491, 0.9804864584, 0.1907753255));
            (* from inside: the way out *)
            (v 0. 0. (-0.5), v 0. 0. 1., (0., 0., 0.5029182255), (-0.3494658948, 0., 0.9369490853)) ];
        List.iter (check cu)
          [ (v 0. 0. (-5.), v 0. 0. 1., (0., 0., -1.1521441994), (0.8006510844, 0., -0.5991309047));
            (v 0.3 0.2 (-5.), v 0. 0. 1., (0.3, 0.2, -0.4793117570), (-0.7485837245, 0.2554183615, -0.6118691592));
            (v (-5.) 0.1 0.2, v 1. 0. 0., (-0.8426412654, 0.1, 0.2), (-0.8770580433, -0.4216553082, -0.2301651359));
            (v 0.1 5. 0.2, v 0. (-1.) 0., (0.1, 0.7686501643, 0.2), (0.9679233246, 0.2362007936, 0.0856365737)) ]);
    Alcotest.test_case "julia_fractal: bad parameters" `Quick (fun () ->
        let bad r = match r with Ok _ -> false | Error _ -> true in
        Alcotest.(check bool) "3-vector" true (bad (Julia.make ~c:[| 0.; 0.; 0. |] ~hypercomplex:false ~cube:false ~max_iteration:8 ~precision:1.));
        Alcotest.(check bool) "0 iterations" true (bad (Julia.make ~c:c1 ~hypercomplex:false ~cube:false ~max_iteration:0 ~precision:1.));
        Alcotest.(check bool) "precision 0" true (bad (Julia.make ~c:c1 ~hypercomplex:false ~cube:false ~max_iteration:8 ~precision:0.));
        Alcotest.(check bool) "hypercomplex cube" true
          (bad (Julia.make ~c:c1 ~hypercomplex:true ~cube:true ~max_iteration:8 ~precision:1.)));
    Alcotest.test_case "julia_fractal: hypercomplex, as POV-Ray traces it" `Quick (fun () ->
        (* povray 3.7 trace() on julia_fractal { <-0.083,0,-0.83,-0.025>
           hypercomplex sqr max_iteration 8 precision 15 } and
           { <-0.745,0,0.113,0.05> hypercomplex max_iteration 9 precision 20 }
           (objects/fractal4.pov's parameters) *)
        let h1 = mk ~hypercomplex:true c1 false 8 in
        let h2 = mk ~hypercomplex:true ~precision:20. [| -0.745; 0.; 0.113; 0.05 |] false 9 in
        List.iter (check h1)
          [ (v 0. 0. (-5.), v 0. 0. 1., (0., 0., -0.9800288459), (0.3085967803, 0.6718131842, -0.6733758777));
            (v 0.3 0.2 (-5.), v 0. 0. 1., (0.3, 0.2, -0.1764329287), (-0.2261680645, 0.6872666234, -0.6902989171));
            (v (-5.) 0.1 0.2, v 1. 0. 0., (-0.3629285927, 0.1, 0.2), (-0.9890313454, -0.1040699148, -0.1048162705));
            (v 0.1 5. 0.2, v 0. (-1.) 0., (0.1, 0.6352572440, 0.2), (0.6229495615, 0.5531556392, -0.5531298967));
            (v 0. 0. (-0.5), v 0. 0. 1., (0., 0., 0.5508528848), (-0.8843140983, -0.2602043118, 0.3876626004)) ];
        List.iter (check h2)
          [ (v 0.2 0.1 (-5.), v 0. 0. 1., (0.2, 0.1, -0.5673751947), (0.4744921545, 0.6224353031, -0.6224399479));
            (v (-5.) 0.05 0.1, v 1. 0. 0., (-1.4040170967, 0.05, 0.1), (-0.7351438983, 0.4793541137, 0.4793569468)) ];
        Alcotest.(check bool) "inside" true (Shape.inside h1 (v 0.1 0.1 0.1));
        Alcotest.(check bool) "outside" false (Shape.inside h1 (v 0.5 0.6 0.2)));
  ]

let sor_units =
  let pts = [| (0., -0.5); (1., 0.); (0.5, 0.6); (1.5, 1.2); (0.8, 2.); (0.3, 3.) |] in
  let mk open_ = match Sor.make ~open_ pts with Ok s -> Shape.Sor s | Error e -> Alcotest.fail e in
  let closed = mk false and opened = mk true in
  let cross s o d =
    let r = Ray.make o d in
    let h = Hit.create infinity in
    if Shape.hit s r 0. h then let p = Ray.at r h.t in Some (p, Shape.normal s p h) else None
  in
  [
    Alcotest.test_case "sor: radii and normals as POV-Ray traces them" `Quick (fun () ->
        List.iter
          (fun (y, rx, nx, ny) ->
            match cross closed (Vec3.make 5. y 0.) (Vec3.make (-1.) 0. 0.) with
            | Some (p, n) ->
                Alcotest.(check (float 1e-6)) (Printf.sprintf "radius at %g" y) rx p.x;
                Alcotest.(check (float 1e-5)) (Printf.sprintf "normal x at %g" y) nx n.x;
                Alcotest.(check (float 1e-5)) (Printf.sprintf "normal y at %g" y) ny n.y
            | None -> Alcotest.failf "missed at %g" y)
          [ (0.01, 1.0040439, 0.942393, -0.334509); (0.3, 0.8135919, 0.593527, 0.804814);
            (0.6, 0.5, 0.923077, -0.384615); (0.9, 1.1104214, 0.424631, -0.905367);
            (1.5, 1.3751075, 0.735917, 0.677072); (1.99, 0.8069879, 0.807579, 0.589759) ]);
    Alcotest.test_case "sor: caps unless open; inside; bounds" `Quick (fun () ->
        let down s x = cross s (Vec3.make x 5. 0.) (Vec3.make 0. (-1.) 0.) in
        (match down closed 0.2 with
         | Some (p, n) -> Alcotest.(check (float 1e-9)) "top cap" 2. p.y; Alcotest.(check (float 0.)) "up" 1. n.y
         | None -> Alcotest.fail "no top cap");
        (match cross closed (Vec3.make 0.7 (-5.) 0.) (Vec3.make 0. 1. 0.) with
         | Some (p, n) -> Alcotest.(check (float 1e-9)) "bottom cap" 0. p.y; Alcotest.(check (float 0.)) "down" (-1.) n.y
         | None -> Alcotest.fail "no bottom cap");
        Alcotest.(check bool) "open: through the top" true (down opened 0.2 = None);
        (match down opened 0.7 with
         | Some (p, _) -> Alcotest.(check (float 1e-6)) "open: the wall below" 0.7238736 p.y
         | None -> Alcotest.fail "open: missed the wall");
        Alcotest.(check (list bool)) "inside" [ true; false; false; true ]
          [ Shape.inside closed (Vec3.make 0.3 1. 0.); Shape.inside closed (Vec3.make 1.6 1. 0.);
            Shape.inside closed (Vec3.make 0.2 2.5 0.); Shape.inside opened (Vec3.make 0.3 1. 0.) ];
        match Shape.bounds closed with
        | Some (lo, hi) ->
            Alcotest.(check (float 1e-6)) "widest" 1.504536 hi.x;
            Alcotest.(check (float 0.)) "bottom" 0. lo.y;
            Alcotest.(check (float 0.)) "top" 2. hi.y
        | None -> Alcotest.fail "unbounded");
    Alcotest.test_case "sor: bad profiles" `Quick (fun () ->
        let err p = match Sor.make ~open_:false p with Ok _ -> "" | Error e -> e in
        Alcotest.(check string) "3 points" "a sor needs at least 4 points, found 3" (err [| (1., 0.); (1., 1.); (1., 2.) |]);
        Alcotest.(check bool) "falling" true (err [| (1., 0.); (1., 1.); (1., 0.5); (1., 2.) |] <> "");
        (* POV-Ray's sor1.pov: the first point level with the second *)
        Alcotest.(check string) "first two level" "" (err [| (0., 0.); (0.1, 0.); (0.6, 0.5); (0.2, 0.8); (0.3, 1.) |]));
  ]

(* POV-Ray 3.7's sphere arithmetic: trace() of povray 3.7 on random
   spheres, printed to 20 decimals (the same doubles; 17 of 40 such
   traces differed with the stable quadratic camlray used before) *)
let pov_spheres =
  Alcotest.test_case "sphere crossings = POV-Ray's doubles" `Quick (fun () ->
      let cases =
        [ ("<-0.28572267894108805,0.3586343164829757,2.545263504142376>, 1.3244301542195014",
           "<0.12546036899633783,1.3981572615983513,-5.045434498321974>, <-0.3827931587805968,-0.7298858810144384,8.289147330482177>",
           (-0.16832110820259466033, 0.83799324771123850919, 1.31622033173315156063));
          ("<-2.4352592626246894,-1.179592424252847,-2.4559767750489634>, 2.0812179756077906",
           "<3.095015720659825,-7.329914618082464,7.715094732780452>, <-3.7892029361966975,6.726945612384716,-9.73815138728762>",
           (-0.54575848086683453886, -0.86647350578731341386, -1.64159872977243104231));
          ("<-2.0550354291590254,-2.9099955783023708,0.17028759702287255>, 0.43101243137148093",
           "<-4.956667795233134,-4.128911781356564,-7.518678572403383>, <2.8736519140717345,1.1727789126528227,7.954628798040844>",
           (-2.29811832100579715998, -3.04391928579704851288, -0.15948029750153036588));
          ("<-2.767821169837304,2.7760890687336914,-1.5695568439441034>, 1.8500748132284295",
           "<-3.8882976268750085,5.179485548117643,1.5434609044789678>, <0.4325883440483832,-3.4842469755294116,-2.3792114941575226>",
           (-3.61815457362406345254, 3.00364070809899708081, 0.05768934774564682400)) ]
      in
      List.iteri
        (fun i (sphere, ray, (x, y, z)) ->
          let got = Scn.vec ~prelude:(Printf.sprintf "#declare S = sphere { %s }" sphere) (Printf.sprintf "trace(S, %s)" ray) in
          Alcotest.(check (list (float 0.))) (Printf.sprintf "trace %d" i) [ x; y; z ] got)
        cases)

(* POV-Ray 3.7's plane keeps its own numbers through translate, rotate
   and scale (planes.cpp): trace() points and normals of povray 3.7, 20
   decimals (8 of 19 crossings agreed when camlray kept a transformation) *)
let pov_planes =
  Alcotest.test_case "transformed planes = POV-Ray's doubles" `Quick (fun () ->
      let cases =
        [ ("<-0.853,-0.803,-0.966>, 0.316 rotate <-4.776,39.137,5.659> scale 1.751 scale 1.931",
           "<-2.672,0.453,2.314>, <0.603,-0.219,-0.723>",
           (-1.65479288625623266462, 0.08356657063037303823, 1.09436360988931391525),
           (-0.74696639183342716795, -0.65683317016079223460, -0.10301163064370272293));
          ("<0.758,0.368,-0.864>, 0.594 translate <1.513,0.483,-0.841>", "<1.37,-4.607,0.457>, <-0.287,-0.494,-0.471>",
           (-142.76596501258268290258, -252.70165754779046096701, -236.08669171054509661190),
           (0.62808199898909933268, 0.30492635307122500921, -0.71591404634113697814));
          ("<0.435,0.392,0.372>, -0.682 rotate <28.8,-13.466,17.616>", "<1.359,1.592,-0.502>, <0.235,0.743,-0.813>",
           (2.20136427143791291172, 4.25530490926965576648, -3.41622192629371479455),
           (0.34481821709552801236, 0.35797374564156841936, 0.86772990877945821442));
          ("<-0.126,-0.084,0.462>, -1.82 rotate <-32.934,-21.883,-37.459> translate <-1.338,0.656,0.218>",
           "<2.099,0.144,3.739>, <0.175,-0.907,0.365>",
           (3.70638740155889223615, -8.18685927550808578701, 7.09155086610854645812),
           (-0.22862812431402429469, 0.64333160739163586239, 0.73065287497110797954)) ]
      in
      List.iteri
        (fun i (plane, ray, (x, y, z), (nx, ny, nz)) ->
          let prelude = Printf.sprintf "#declare S = plane { %s }\n#declare N = <0,0,0>;" plane in
          let got = Scn.vec ~prelude (Printf.sprintf "trace(S, %s, N)" ray) in
          Alcotest.(check (list (float 0.))) (Printf.sprintf "trace %d" i) [ x; y; z ] got;
          let n = Scn.vec ~prelude:(prelude ^ Printf.sprintf "\n#declare P = trace(S, %s, N);" ray) "N" in
          Alcotest.(check (list (float 0.))) (Printf.sprintf "normal %d" i) [ nx; ny; nz ] n)
        cases)

let tests =
  ("shape", folded :: pov_spheres :: pov_planes :: hand @ inside_cases @ hf_units @ polygon_units @ patch_units @ algebraic_units @ blob_units @ prism_units @ lathe_units @ sor_units @ julia_units @ superellipsoid_units @ iso_units
    @ List.map QCheck_alcotest.to_alcotest (roots_prop :: cubic_roots_prop :: prism_prop :: prism_window_prop :: lathe_prop :: superellipsoid_prop :: props))
