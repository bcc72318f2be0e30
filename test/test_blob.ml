(* Blobs whose components are placed by transformations of their own and
   carry textures of their own (POV-Ray's blob.cpp): qcheck properties of
   the placed field and of the hits, the texture weights against hand
   computations, a render's known answer, the parser's rules. *)
open Camlray
open Geom_gen

let close ?(eps = 1e-9) a b = Float.abs (a -. b) <= eps *. (1. +. Float.abs a +. Float.abs b)

(* a sphere or a cylinder, and an uneven placement: a stretch by 0.3 to
   3 on each axis, a turn, a move *)
let gcomp =
  let open QCheck.Gen in
  oneof
    [
      map3 (fun center radius strength -> Blob.Sphere { center; radius; strength }) (gvec 0.8) (fr 0.4 1.2)
        (fr (-1.5) 1.5);
      map3
        (fun a d (radius, strength) -> Blob.Cylinder { a; b = Vec3.madd a 1.2 d; radius; strength })
        (gvec 0.8) gdir
        (pair (fr 0.3 1.) (fr (-1.5) 1.5));
    ]

let gstretch =
  let open QCheck.Gen in
  map3
    (fun r s t -> Transform.then_ (Transform.then_ (Transform.scale s) (Transform.rotate r)) (Transform.translate t))
    (gvec 180.) (map3 Vec3.make (fr 0.3 3.) (fr 0.3 3.) (fr 0.3 3.)) (gvec 1.)

let print_comp = function
  | Blob.Sphere { center; radius; strength } ->
      Printf.sprintf "sphere %s r %g s %g" (Vec3.to_string center) radius strength
  | Blob.Cylinder { a; b; radius; strength } ->
      Printf.sprintf "cylinder %s %s r %g s %g" (Vec3.to_string a) (Vec3.to_string b) radius strength
  | Blob.Placed _ -> "placed"

let field_through =
  QCheck.Test.make ~name:"a placed component's field is its own field through the inverse transform" ~count:2000
    (QCheck.make
       ~print:(fun (c, t, p) -> Printf.sprintf "%s by %s at %s" (print_comp c) (Transform.to_string t) (Vec3.to_string p))
       QCheck.Gen.(triple gcomp gstretch (gvec 3.)))
    (fun (c, t, p) ->
      let placed = Blob.make ~threshold:0.5 [ Blob.place t c ] and own = Blob.make ~threshold:0.5 [ c ] in
      let q = Transform.inv_point t p in
      let a = Blob.field placed p.x p.y p.z and b = Blob.field own q.x q.y q.z in
      if not (close ~eps:1e-12 a b) then QCheck.Test.fail_reportf "placed %.17g, through the inverse %.17g" a b;
      (* placing twice is placing by the composition *)
      let t2 = Transform.scale (Vec3.make 1.5 0.5 1.) in
      let twice = Blob.make ~threshold:0.5 [ Blob.place t2 (Blob.place t c) ] in
      let r = Transform.point t2 p in
      let d = Blob.field twice r.x r.y r.z in
      if not (close ~eps:1e-12 a d) then QCheck.Test.fail_reportf "placed twice %.17g, once %.17g" d a;
      true)

(* Blobs of two to four components, some placed unevenly, threshold 0.3 *)
let gblob =
  let open QCheck.Gen in
  let comp = map3 (fun c t placed -> if placed then Blob.place t c else c) gcomp gstretch bool in
  map (fun cs -> (cs, Blob.make ~threshold:0.3 cs)) (list_size (int_range 2 4) comp)

let hits_on_surface =
  QCheck.Test.make ~name:"hits of blobs with placed components: on the threshold surface, the first, normal against the gradient"
    ~count:3000
    (QCheck.make
       ~print:(fun ((cs, _), r) ->
         Printf.sprintf "%d components, ray %s + t %s" (List.length cs) (Vec3.to_string r.Ray.origin)
           (Vec3.to_string r.dir))
       QCheck.Gen.(pair gblob gray))
    (fun ((_, b), r) ->
      let h = Hit.create infinity in
      if not (Shape.hit (Shape.Blob b) r 1e-9 h) then true
      else begin
        let f t =
          let p = Ray.at r t in
          Blob.field b p.x p.y p.z
        in
        (* the field's distance from the threshold, over its slope along
           the ray: the hit's error in t *)
        let e = 1e-7 *. (1. +. h.t) in
        let slope = (f (h.t +. e) -. f (h.t -. e)) /. (2. *. e) in
        let err = Float.abs (f h.t -. 0.3) /. Float.abs slope in
        if err > 1e-7 *. (1. +. h.t) && Float.abs (f h.t -. 0.3) > 1e-12 then
          QCheck.Test.fail_reportf "field %.17g at t = %g (error in t %g)" (f h.t) h.t err;
        (* the normal: against the field's gradient (central differences) *)
        let p = Ray.at r h.t in
        let g x y z = Blob.field b x y z and d = 1e-6 in
        let grad =
          Vec3.make
            ((g (p.x +. d) p.y p.z -. g (p.x -. d) p.y p.z) /. (2. *. d))
            ((g p.x (p.y +. d) p.z -. g p.x (p.y -. d) p.z) /. (2. *. d))
            ((g p.x p.y (p.z +. d) -. g p.x p.y (p.z -. d)) /. (2. *. d))
        in
        let n = Shape.normal (Shape.Blob b) p h in
        if Vec3.length grad > 1e-3 then begin
          let want = Vec3.scale (-1. /. Vec3.length grad) grad in
          if Vec3.length (Vec3.sub n want) > 1e-4 then
            QCheck.Test.fail_reportf "normal %s, against the gradient %s" (Vec3.to_string n) (Vec3.to_string want)
        end;
        (* the first crossing: from outside, the field stays below the
           threshold before it (sampled) *)
        if f 1e-9 < 0.3 then
          for i = 1 to 199 do
            let t = h.t *. float i /. 200. in
            if f t > 0.3 +. 1e-9 then QCheck.Test.fail_reportf "inside at t = %g, before the hit at %g" t h.t
          done;
        true
      end)

(* Two spheres of radius 1, 1 apart, strengths [s1] and [s2]: at a point
   as far from both (the plane x = 0) each weighs its strength *)
let v = Vec3.make

let weights_known =
  Alcotest.test_case "texture weights: shares of the fields, absolute values, zero outside" `Quick (fun () ->
      let sph c k = Blob.Sphere { center = c; radius = 1.; strength = k } in
      let b = Blob.make ~threshold:0.5 [ sph (v (-0.5) 0. 0.) 1.; sph (v 0.5 0. 0.) (-3.); sph (v 5. 0. 0.) 1. ] in
      let ws = Float.Array.make 3 0. and ix = Array.make 3 0 in
      let p = Vec3.m () in
      Vec3.set p 0. 0.3 0.;
      let n = Blob.weights b p ws ix in
      Alcotest.(check int) "two count (the third is out of reach)" 2 n;
      Alcotest.(check (list int)) "which" [ 0; 1 ] [ ix.(0); ix.(1) ];
      Alcotest.(check (float 1e-15)) "first: 1 / (1 + 3)" 0.25 (Float.Array.get ws 0);
      Alcotest.(check (float 1e-15)) "second: |-3| / (1 + 3)" 0.75 (Float.Array.get ws 1);
      (* at the first's centre, on the second's edge (d = r: no field) *)
      Vec3.set p (-0.5) 0. 0.;
      Alcotest.(check int) "one counts" 1 (Blob.weights b p ws ix);
      Alcotest.(check (float 0.)) "the whole" 1. (Float.Array.get ws 0);
      (* nearer the first: (1 - d1^2)^2 against |-3| (1 - d2^2)^2 *)
      Vec3.set p (-0.2) 0. 0.;
      let _ = Blob.weights b p ws ix in
      let f1 = (1. -. 0.09) ** 2. and f2 = 3. *. ((1. -. 0.49) ** 2.) in
      Alcotest.(check (float 1e-15)) "in between" (f1 /. (f1 +. f2)) (Float.Array.get ws 0);
      (* a placed component weighs its field in its own space *)
      let st = Transform.scale (v 2. 1. 1.) in
      let c = Blob.make ~threshold:0.5 [ Blob.place st (sph Vec3.zero 1.); sph (v 0. 1. 0.) 1. ] in
      Vec3.set p 1. 0.5 0.;
      let _ = Blob.weights c p ws ix in
      (* own space: (0.5, 0.5, 0), d^2 = 0.5; the other: d^2 = 1.25, out *)
      Alcotest.(check (float 1e-15)) "stretched: alone" 1. (Float.Array.get ws 0);
      Vec3.set p 0.6 0.5 0.;
      let _ = Blob.weights c p ws ix in
      let f1 = (1. -. (0.09 +. 0.25)) ** 2. and f2 = (1. -. (0.36 +. 0.25)) ** 2. in
      Alcotest.(check (float 1e-15)) "stretched: shared" (f1 /. (f1 +. f2)) (Float.Array.get ws 0))

(* Orthographic rays along z through x = 0, where two spheres of radius 1
   at x = -0.5 and 0.5 are as far: the surface's colour is the shares of
   their strengths. Lit by ambient light alone (ambient 1, diffuse 0),
   the pixel is the texture's colour. *)
let render_known =
  Alcotest.test_case "a two-texture blob's colour: the fields' shares, small shares left out" `Quick (fun () ->
      let scene s1 s2 =
        Printf.sprintf
          "camera { orthographic location <0, 0, -5> look_at 0 right x*0.02 up y*0.02 }\n\
           global_settings { ambient_light 1 }\n\
           #default { finish { ambient 1 diffuse 0 } }\n\
           blob { threshold 0.5\n\
          \  sphere { <-0.5, 0, 0>, 1, %g pigment { rgb <1, 0, 0> } }\n\
          \  sphere { <0.5, 0, 0>, 1, %g scale <1, 1, 1> } \n\
          \  pigment { rgb <0, 0, 1> } }"
          s1 s2
      in
      let px s1 s2 = Helpers.pixel (Helpers.render_whitted ~width:1 ~height:1 (scene s1 s2)) 0 0 in
      let r, g, b = px 1. 2. in
      Alcotest.(check (float 1e-6)) "red: 1/3" (1. /. 3.) r;
      Alcotest.(check (float 1e-6)) "green" 0. g;
      Alcotest.(check (float 1e-6)) "blue: 2/3 (the blob's own texture)" (2. /. 3.) b;
      (* a share of 1/500, below adc_bailout (1/255), is left out and the
         other is not scaled up (POV-Ray's trace.cpp) *)
      let r, _, b = px 1. 499. in
      Alcotest.(check (float 1e-6)) "red left out" 0. r;
      Alcotest.(check (float 1e-6)) "blue as it is" (499. /. 500.) b)

(* How the parser reads a component's modifiers: a checker with cells 1
   wide, scaled by 2 when written before the scale, not after *)
let parse_rules =
  Alcotest.test_case "component textures: moved by the transformations after them, the blob's after" `Quick
    (fun () ->
      let comp text =
        match (Scn.parse text).items with
        | [ Camlray_lang.Sdl.Object { shape = Camlray_lang.Sdl.Blob (_, [ c ]); _ } ] -> c
        | _ -> Alcotest.fail "expected one blob of one component"
      in
      let colour (c : Camlray_lang.Sdl.blob_component) p =
        match c.ctex with
        | Some (l :: _) -> (Pigment.eval l.pigment p).c.r
        | _ -> Alcotest.fail "no texture"
      in
      let p = v 1.5 0.5 0.5 in
      (* cells of 1: 1 + 0 + 0 is odd, the second colour; of 2: even *)
      let before = comp "blob { sphere { 0, 1, 1 pigment { checker rgb 1 rgb 0 } scale <2, 2, 2> } }" in
      Alcotest.(check (float 0.)) "written before the scale: moved" 1. (colour before p);
      let after = comp "blob { sphere { 0, 1, 1 scale <2, 2, 2> pigment { checker rgb 1 rgb 0 } } }" in
      Alcotest.(check (float 0.)) "written after: not moved" 0. (colour after p);
      (* an uneven scale places the component; its texture moves with it *)
      let st = comp "blob { sphere { 0, 1, 1 pigment { checker rgb 1 rgb 0 } scale <2, 1, 1> } }" in
      (match st.comp with Blob.Placed _ -> () | _ -> Alcotest.fail "a stretched sphere is placed");
      Alcotest.(check (float 0.)) "stretched with it" 1. (colour st (v 1.5 0.5 0.5));
      (* the blob's transformation moves its components' textures, at
         compile time: the field's textures by component *)
      let s =
        Helpers.compile_string
          "blob { sphere { 0, 1, 1 pigment { checker rgb 1 rgb 0 } } sphere { x, 1, 1 } scale 2 }"
      in
      match s.objects.(0).texture with
      | [ { tmap = Some { kind = Texture.Field _; entries; _ }; _ } ] -> (
          Alcotest.(check int) "an entry per component" 2 (Array.length entries);
          match snd entries.(0) with
          | l :: _ -> Alcotest.(check (float 0.)) "scaled with the blob" 1. (Pigment.eval l.pigment p).c.r
          | [] -> Alcotest.fail "empty entry")
      | _ -> Alcotest.fail "expected a blob field texture")

(* POV-Ray's depth tolerance for blobs (blob.cpp, 0.01): one component of
   strength 1 at threshold 1/4 has its surface at sqrt(1/2) of its
   radius. A crossing nearer than 0.01 to the origin, a distance in the
   world, is not taken; ends of a component's stretch nearer than 0.01 in
   the blob's own units are moved to 0 (a stretch ending there is
   dropped; one starting there counts from 0, where its quartic rises
   again outside the component). *)
let depth_tolerance =
  Alcotest.test_case "depth tolerance: crossings within 0.01 in the world, stretch ends within 0.01 in the blob" `Quick
    (fun () ->
      let r = Float.sqrt 0.5 in
      let sph rad = Blob.Sphere { center = Vec3.zero; radius = rad; strength = 1. } in
      let unit = Object.make (Shape.Blob (Blob.make ~threshold:0.25 [ sph 1. ])) in
      let hit o orig d = Object.intersect o (Ray.make orig d) 1e-9 infinity in
      let z = v 0. 0. 1. in
      Alcotest.(check (float 1e-9)) "0.02 ahead: taken" 0.02 (hit unit (v 0. 0. (-.(r +. 0.02))) z);
      Alcotest.(check (float 1e-9)) "0.005 ahead: the far side instead" (0.005 +. (2. *. r))
        (hit unit (v 0. 0. (-.(r +. 0.005))) z);
      (* a direction of length 2: 0.004 along it is 0.008 away, 0.006 is 0.012 *)
      let z2 = v 0. 0. 2. in
      Alcotest.(check (float 1e-9)) "0.008 away along a long direction: not taken" ((0.008 +. (2. *. r)) /. 2.)
        (hit unit (v 0. 0. (-.(r +. 0.008))) z2);
      Alcotest.(check (float 1e-9)) "0.012 away: taken" 0.006 (hit unit (v 0. 0. (-.(r +. 0.012))) z2);
      (* radius 0.02, scaled by 100: 0.01 in the blob is 1 in the world;
         the surface at 100 * 0.02 * sqrt(1/2) *)
      let big =
        Object.make ~xform:(Transform.scale (v 100. 100. 100.)) (Shape.Blob (Blob.make ~threshold:0.25 [ sph 0.02 ]))
      in
      let x = v 1. 0. 0. and mx = v (-1.) 0. 0. in
      let surface = 2. *. r in
      (* from inside, outward: the stretch ends 0.007 (blob) ahead and is
         dropped, the crossing 0.114 ahead in the world with it *)
      Alcotest.(check (float 0.)) "stretch ending within 0.01: no field, no crossing" infinity
        (hit big (v 1.3 0. 0.) x);
      Alcotest.(check (float 1e-9)) "ending 0.011 ahead: kept" (surface -. 0.9) (hit big (v 0.9 0. 0.) x);
      (* from outside, inward, entering 0.008 (blob) ahead: counted from
         0, where (1 - d^2/R^2)^2 is 0.9216 (d = 1.4 R); it falls to 1/4
         at d^2 = 1.5 R^2, 0.35051 ahead in the world, outside the
         component: a crossing there, the normal +x (no component's
         gradient: POV-Ray's default) *)
      let t = hit big (v 2.8 0. 0.) mx in
      Alcotest.(check (float 1e-9)) "stretch starting within 0.01: a shell outside it" (2.8 -. (2. *. Float.sqrt 1.5)) t;
      let n = Object.normal big (v (2.8 -. t) 0. 0.) (Hit.create t) in
      Alcotest.(check (float 1e-12)) "its normal: +x" 1. n.x;
      (* entering 0.012 ahead: as it is, the surface *)
      Alcotest.(check (float 1e-9)) "starting 0.012 ahead: the surface" (3.2 -. surface) (hit big (v 3.2 0. 0.) mx))

let tests =
  ( "blob",
    [ weights_known; render_known; parse_rules; depth_tolerance ]
    @ List.map QCheck_alcotest.to_alcotest [ field_through; hits_on_surface ] )
