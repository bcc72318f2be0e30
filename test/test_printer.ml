(* parse (print sdl) = sdl: random shapes and lights printed by Printer
   and read back by Parse (transforms compared by their action on points,
   everything else exactly). *)
open Camlray
open Camlray_lang

let gen_float = QCheck.Gen.(oneof [ float_range (-10.) 10.; oneof_list [ 0.; 1.; 0.1; 1e-7; 123456.789 ] ])
let gen_pos = QCheck.Gen.(oneof [ float_range 0.01 10.; oneof_list [ 1.; 0.5; 1e-3 ] ])
let gen_vec = QCheck.Gen.(map3 Vec3.make gen_float gen_float gen_float)
let gen_col = QCheck.Gen.(map3 Color.make gen_pos gen_pos gen_pos)
let gen_bool = QCheck.Gen.bool

let gen_xform =
  QCheck.Gen.(
    list_size (int_bound 4)
      (oneof
         [
           map Transform.translate gen_vec;
           map Transform.rotate gen_vec;
           map (fun (a, b, c) -> Transform.scale (Vec3.make a b c)) (triple gen_pos gen_pos gen_pos);
         ])
    |> map (List.fold_left Transform.then_ Transform.identity))

let gen_finish =
  QCheck.Gen.(
    map
      (fun ((amb, em, d, db), (br, ph, ps, sp), (ro, me, rmin, rmax), (fr, fo, ex, ce)) ->
        { Finish.ambient = amb; emission = em; diffuse = d; diffuse_back = db; brilliance = br;
          phong = ph; phong_size = ps; specular = sp; roughness = ro; metallic = me;
          reflection = { rmin; rmax; falloff = fo; fresnel = fr; exponent = ex; rmetallic = me };
          conserve_energy = ce; double_illuminate = false;
          irid = 0.; irid_thickness = 0.; irid_turb = 0. })
      (quad (quad gen_col gen_col gen_pos gen_pos) (quad gen_pos gen_pos gen_pos gen_pos)
         (quad gen_pos gen_pos gen_col gen_col) (quad gen_bool gen_pos gen_pos gen_bool)))

let gen_layer =
  QCheck.Gen.(
    map2
      (fun (c, f, t) finish -> Texture.layer (Pigment.Solid { c; filter = f; transmit = t }) finish)
      (triple gen_col gen_pos gen_pos) gen_finish)

let gen_interior =
  QCheck.Gen.(
    map (fun (ior, fd, fp, fc) -> { Interior.ior; fade_distance = fd; fade_power = fp; fade_color = fc; hollow = false; caustics = 0.; media = []; slot = 0 })
      (quad gen_pos gen_pos gen_pos gen_col))

let gen_obj =
  QCheck.Gen.(
    map
      (fun (shape, xform, texture, (interior, no_shadow, (hollow, flags))) ->
        { Sdl.loc = Loc.none; shape; xform; texture; interior; no_shadow; hollow; flags; inner = None;
          photon = Photon.none })
      (quad
         (oneof
            [
              map2 (fun c r -> Sdl.Sphere (c, r)) gen_vec gen_pos;
              map2 (fun n d -> Sdl.Plane (Vec3.add n (Vec3.make 0. 20. 0.), d)) gen_vec gen_float;
              map2 (fun a (dx, dy, dz) -> Sdl.Box (a, Vec3.add a (Vec3.make dx dy dz))) gen_vec
                (triple gen_pos gen_pos gen_pos);
              map2 (fun r1 r2 -> Sdl.Torus (r1 +. r2, r2)) gen_pos gen_pos;
              map3 (fun a b c -> Sdl.Triangle (a, b, c)) gen_vec gen_vec gen_vec;
              map3
                (fun a d (r, o) ->
                  Sdl.Cone { base = a; base_r = r; top = Vec3.add a (Vec3.add d (Vec3.make 0. 20. 0.));
                             top_r = r; open_ = o; cylinder = true })
                gen_vec gen_vec (pair gen_pos gen_bool);
              (* poly, cubic, quartic (printed as poly) and quadric *)
              (int_range 2 5 >>= fun k ->
               map (fun cs -> Sdl.Algebraic { order = k; coef = Array.of_list cs; quadric = false })
                 (list_size (return (Algebraic.terms k)) gen_float));
              map (fun cs -> Sdl.Algebraic { order = 2; coef = Array.of_list cs; quadric = true })
                (list_size (return 10) gen_float);
              map3
                (fun p c ((fd, fp, sh), (k, at, par)) ->
                  (* the states POV-Ray's keywords can reach: shadowless
                     only on a point light (it makes one), a cylinder
                     always parallel, point_at on a point light only
                     when parallel or shadowless (left from a spotlight) *)
                  let kind, par =
                    match k with
                    | 0 -> (Sdl.Point_light, par)
                    | 1 -> (Sdl.Spot_light { radius = fd; falloff = fp; tightness = fd +. fp }, par)
                    | _ -> (Sdl.Cylinder_light { radius = fp; falloff = fd; tightness = 2. }, true)
                  in
                  let sh = sh && kind = Sdl.Point_light in
                  let at = if kind = Sdl.Point_light && not (par || sh) then Vec3.unit_z else at in
                  Sdl.Light
                    { Sdl.position = p; color = c; kind; point_at = at; parallel = par; fade_distance = fd;
                      fade_power = fp; shadowless = sh; media_interaction = not sh;
                      media_attenuation = sh; area = None; looks_like = None; projected_through = None })
                gen_vec gen_col
                (pair (triple gen_pos gen_pos gen_bool) (triple (int_range 0 2) gen_vec gen_bool));
            ])
         gen_xform
         (option (list_size (int_range 1 3) gen_layer))
         (triple (option gen_interior) gen_bool (pair gen_bool (int_range 0 7)))))

let same_xform a b =
  List.for_all
    (fun p ->
      let close (u : Vec3.t) (v : Vec3.t) = Vec3.length (Vec3.sub u v) <= 1e-9 *. (1. +. Vec3.length u) in
      close (Transform.point a p) (Transform.point b p) && close (Transform.inv_point a p) (Transform.inv_point b p))
    [ Vec3.zero; Vec3.unit_x; Vec3.unit_y; Vec3.unit_z; Vec3.make 3. (-2.) 5. ]

let normalise (o : Sdl.obj) =
  (* lights keep no texture or interior *)
  match o.shape with
  | Sdl.Light _ -> { o with texture = None; interior = None; no_shadow = false; hollow = false; flags = 0; inner = None; photon = Photon.none }
  | _ -> o

let round_trip =
  QCheck.Test.make ~name:"Printer: parse (print obj) = obj" ~count:300
    (QCheck.make ~print:(fun o -> Printer.obj (normalise o)) gen_obj)
    (fun o ->
      let o = normalise o in
      let text = Printer.obj o in
      match Parse.string text with
      | Ok { Sdl.items = [ Sdl.Object o' ]; _ } ->
          let strip (x : Sdl.obj) = { x with loc = Loc.none; xform = Transform.identity } in
          if not (same_xform o.xform o'.xform) then QCheck.Test.fail_reportf "transforms differ"
          else if strip o <> strip o' then QCheck.Test.fail_reportf "read back:\n%s" (Printer.obj o')
          else true
      | Ok _ -> QCheck.Test.fail_reportf "not one object"
      | Error d -> QCheck.Test.fail_reportf "%s" (Diag.to_string d))

(* CSG, inverse, clipped_by, meshes: print (parse (print s)) = print s *)
let fixpoint () =
  let text =
    "union { sphere { 0, 1 } box { -1, 1 inverse translate x } pigment { rgb 1 } scale 2 }\n\
     difference { cylinder { 0, y, 1 open } cone { 0, 1, y, 0.5 } rotate 30*z }\n\
     sphere { 0, 1 clipped_by { plane { y, 0 } } translate 3*z }\n\
     mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }\n\
     disc { 0, y, 2, 0.5 } smooth_triangle { 0, y, x, y, z, y } torus { 2, 0.5 }\n\
     quartic { <1,0,0,0,0,0,0,0,0,-1, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,1,0,0,0,0, 0,0,1,0,0> sturm\n\
       bounded_by { sphere { 0, 2 } } scale 2 }\n\
     cubic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,-1> clipped_by { box { -1, 1 } } bounded_by { clipped_by } }\n\
     quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 clipped_by { plane { y, 1 } } }\n\
     fog { rgb <0.5, 0.6, 0.7> 30 } fog { fog_type 2 distance 4 fog_alt 0.5 fog_offset 1 up <0, 0, 1>\n\
       color rgbft <1, 1, 1, 0.2, 0.1> turbulence 0.3 turb_depth 0.4 octaves 4 omega 0.6 lambda 2.5 }\n\
     blob { threshold 0.4 sphere { 0, 1, 1 } cylinder { -x, x, 0.5, strength -2 } component 1, 1, y sturm\n\
       hierarchy off pigment { rgb 1 } rotate 10*z }\n\
     blob { sphere { 0, 1, 1 pigment { rgb <1, 0, 0> } scale <1, 2, 1> finish { phong 0.5 } }\n\
       cylinder { 0, y, 0.5, 1 rotate 30*x texture { pigment { rgb 0.2 } } texture { pigment { rgbt <0, 1, 0, 0.5> } } } }\n\
     prism { conic_sweep cubic_spline 0.2, 1, 7, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <1, 0>, <1, 1> open }\n\
     lathe { quadratic_spline 4, <0, 0>, <1, 0.5>, <0.5, 1>, <0, 1.5> sturm }\n\
     superellipsoid { <0.3, 2> scale 2 }\n\
     julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion cube max_iteration 8 precision 15 scale 2 }\n\
     sor { 5, <0, 0>, <1, 0.2>, <0.5, 1>, <0.8, 1.5>, <0, 2> open interior_texture { pigment { rgb <1, 0, 0> } } }\n\
     union { sphere { 0, 1 } cylinder { 0, y, 0.5 open } interior_texture { pigment { rgb 0.5 } finish { ambient 0.3 } } }\n\
     height_field { function 4, 3 { x * y + 0.1 } smooth water_level 0.1 hierarchy off scale <2, 1, 2> }\n\
     #declare R = 0.25; #declare N = -2;\n\
     isosurface { function { sqrt(x*x + y*y + z*z) - R + 0.1*sin(4*x) } open max_gradient 2.5 threshold -0.1 translate y }\n\
     isosurface { function { abs(x) + pow(y, 2) - min(z, 0.5) * N } contained_by { sphere { <0, 0.5, 0>, 2 } } accuracy 1e-4\n\
       all_intersections pigment { rgb 1 } }\n\
     isosurface { function (a, b, c) { a*b - c } contained_by { box { -2, <1, 2, 3> } } max_trace 3 }\n\
     light_source { <1, 2, 3>, rgb 1 cylinder point_at 0 radius 0.5 falloff 2 tightness 3 rotate 10*x\n\
       projected_through { sphere { 0, 1 } scale 2 } translate x }\n\
     light_source { 0, rgb 1 spotlight point_at y shadowless parallel }\n"
  in
  let text =
    if Sys.file_exists "/usr/share/povray-3.7/include/timrom.ttf" then
      text ^ "text { ttf \"timrom.ttf\" \"say \\\"hi\\\"\" 0.5, <0.1, 0, 0> rotate 20*y }\n"
    else text
  in
  let print s = String.concat "\n" (List.map Printer.item s.Sdl.items) in
  let parse t = match Parse.string t with Ok s -> s | Error d -> Alcotest.fail (Diag.to_string d) in
  let once = print (parse text) in
  (* what is printed is all there: each kind of object, and the
     modifiers that are easy to drop *)
  List.iter
    (fun w -> if not (Scn.contains once w) then Alcotest.failf "%S is not printed" w)
    [ "sor {"; "interior_texture {"; "isosurface {"; "height_field {"; "lathe {"; "prism {"; "blob {";
      "superellipsoid {"; " open"; "julia_fractal {"; "cube"; " cylinder point_at"; "projected_through {";
      " parallel point_at <0, 1, 0> shadowless" ];
  Alcotest.(check string) "fixpoint" once (print (parse once))

(* declared media and densities, used and edited, in interiors and at
   scene level: printed as plain media that read back equal *)
let media () =
  let text =
    "#declare D = density { rgb <0.5, 0.25, 1> }\n\
     #declare M = media { emission 0.1 absorption <0.1, 0.2, 0.3> density { D } method 2 intervals 2 samples 3 }\n\
     sphere { 0, 1 pigment { rgbt 1 } hollow interior { ior 1.2 media { M emission 0.3 } media { scattering { 5, 0.2 eccentricity 0.4 extinction 0.5 } } } }\n\
     media { M density { D scale 2 } aa_level 2 aa_threshold 0.05 jitter 0.1 }\n\
     media { scattering { 2, <0.1, 0.2, 0.3> } samples 4, 8 confidence 0.8 variance 0.01 ratio 0.7 }\n"
  in
  let parse t = match Parse.string t with Ok s -> s | Error d -> Alcotest.fail (Diag.to_string d) in
  let media_of (s : Sdl.scene) =
    List.concat_map
      (function
        | Sdl.Media m -> [ m ]
        | Sdl.Object { interior = Some i; _ } -> i.Interior.media
        | _ -> [])
      s.items
  in
  let first = parse text in
  let ms = media_of first in
  Alcotest.(check int) "four media" 4 (List.length ms);
  (match ms with
  | m :: _ ->
      Alcotest.(check (float 0.)) "M's emission edited" 0.3 m.Media.emission.r;
      Alcotest.(check (float 0.)) "M's absorption kept" 0.2 m.Media.absorption.g;
      Alcotest.(check int) "M's method kept" 2 m.Media.meth
  | [] -> ());
  let print s = String.concat "\n" (List.map Printer.item s.Sdl.items) in
  let again = parse (print first) in
  if media_of again <> ms then Alcotest.failf "media printed as\n%s\nread back otherwise" (print first);
  Alcotest.(check string) "fixpoint" (print first) (print again)

let tests =
  ( "printer",
    [ QCheck_alcotest.to_alcotest round_trip;
      Alcotest.test_case "CSG, inverse, clipped_by, bounded_by, mesh2, polynomials, fog, blob, prism, lathe, superellipsoid, isosurface print back to themselves" `Quick fixpoint;
      Alcotest.test_case "declared media and densities print back" `Quick media ] )
