(* The classic lighting model against POV-Ray 3.7's measured values
   (pov-facts.md section 5). Scenes look along +z from the origin at a
   plane z = 1; one light 30 degrees off the normal. *)
open Camlray
open Scn

let light30 = "light_source { <5, 0, -7.660254>, rgb 1 }\n"
let plane ?(pig = "rgb 1") fin = Printf.sprintf "plane { z, 1 pigment { %s } finish { %s } }\n" pig fin
let lit ?pig fin = pixel (light30 ^ plane ?pig fin)

let finishes () =
  gray "default finish" 0.61962 (lit "");
  gray "brilliance 2" 0.55 (lit "brilliance 2");
  gray "phong 1 size 10" 0.23730 (lit "ambient 0 diffuse 0 phong 1 phong_size 10");
  gray "phong default size" 0.00317 (lit "ambient 0 diffuse 0 phong 1");
  color "phong on red is white" (0.23730, 0.23730, 0.23730)
    (lit ~pig:"rgb <1,0,0>" "ambient 0 diffuse 0 phong 1 phong_size 10");
  gray "specular 1" 0.49989 (lit "ambient 0 diffuse 0 specular 1");
  gray "specular .5 roughness .01" 0.01561 (lit "ambient 0 diffuse 0 specular 0.5 roughness 0.01");
  color ~eps:1e-4 "phong + metallic on red" (0.2373, 0.0028, 0.0028)
    (lit ~pig:"rgb <1,0,0>" "ambient 0 diffuse 0 phong 1 phong_size 10 metallic");
  color "coloured ambient" (0.2, 0.2, 0.)
    (pixel (plane ~pig:"rgb <1,.5,0>" "ambient <.2,.4,.6> diffuse 0"));
  color "emission" (0.5, 0.25, 0.) (pixel (plane ~pig:"rgb <1,.5,0>" "ambient 0 diffuse 0 emission 0.5"));
  gray "ambient_light" 0.2
    (pixel ("global_settings { ambient_light 0.5 }\n" ^ plane "ambient 0.4 diffuse 0"));
  gray "emission ignores ambient_light" 0.3
    (pixel ("global_settings { ambient_light 0.5 }\n" ^ plane "ambient 0 diffuse 0 emission 0.3"));
  color "light colour per channel" (0.6 *. 0.866025, 0.3 *. 0.866025, 1.2 *. 0.866025)
    (pixel ("light_source { <5, 0, -7.660254>, rgb <1,.5,2> }\n" ^ plane "ambient 0"))

let lights () =
  let spot a = Printf.sprintf
      "light_source { <0,0,0>, rgb 1 spotlight point_at <%f, 0, %f> }\n" (sin a) (cos a) in
  let rad d = d *. Float.pi /. 180. in
  (* camera ray hits (0,0,1); the spot axis is turned away by the angle *)
  let spot_at d = pixel (spot (rad d) ^ plane "ambient 0 diffuse 1") in
  gray "spot at 35" 0.79033 (spot_at 35.);
  gray "spot at 40" 0.31061 (spot_at 40.);
  gray "spot at 46" 0. (spot_at 46.);
  (* looks_like { Name }: the declared object drawn at the light (here in
     front of the camera: its emission seen), casting no shadow *)
  gray "looks_like a declared object" 0.7
    (pixel "#declare Sun = sphere { 0, 0.1 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 0.7 } }\n\
            light_source { <0, 0, 0.5>, rgb 1 looks_like { Sun } }\n");
  gray "spot tight" 0.85805
    (pixel
       (Printf.sprintf
          "light_source { 0, rgb 1 spotlight point_at <%f,0,%f> radius 15 falloff 25 tightness 10 }\n"
          (sin (rad 10.)) (cos (rad 10.))
       ^ plane "ambient 0 diffuse 1"));
  let fade fd fp =
    pixel (Printf.sprintf "light_source { <0,0,-9>, rgb 1 fade_distance %g fade_power %g }\n" fd fp
           ^ plane "ambient 0 diffuse 1")
  in
  gray "fade 5 1 at 10" 0.66667 (fade 5. 1.);
  gray "fade 5 2 at 10" 0.4 (fade 5. 2.);
  gray "fade power 0" 1. (fade 5. 0.);
  gray "parallel" 0.866025
    (pixel ("light_source { <0,0,0>, rgb 1 parallel point_at <-0.5, 0, 0.8660254> }\n"
            ^ plane "ambient 0 diffuse 1"));
  gray "shadowless: no highlight" (0.866025 *. 0.6 +. 0.1)
    (pixel ("light_source { <5, 0, -7.660254>, rgb 1 shadowless }\n" ^ plane "phong 1 phong_size 10"));
  gray "back diffuse" (0.4 *. 0.866025)
    (pixel ("light_source { <5, 0, 9.660254>, rgb 1 }\n" ^ plane "ambient 0 diffuse 0.6, 0.4"))

(* a blocker halfway along the shadow ray of the 30-degree light *)
let shadow pig extra =
  pixel (light30 ^ Printf.sprintf "sphere { <2.5, 0, -3.33>, 0.5 pigment { %s } %s }\n" pig extra
         ^ plane "ambient 0 diffuse 1")

let shadows () =
  let k = 0.866025 in
  gray "opaque blocker" 0. (shadow "rgb 1" "");
  gray "rgbt .5 twice" (0.25 *. k) (shadow "rgbt <1,1,1,.5>" "");
  gray "rgbf .5 white" (0.25 *. k) (shadow "rgbf <1,1,1,.5>" "");
  color "rgbf <1,.5,0,1>" (k, 0.25 *. k, 0.) (shadow "rgbf <1,.5,0,1>" "");
  color "rgbft" (k, 0.5625 *. k, 0.25 *. k) (shadow "rgbft <1,.5,0,.5,.5>" "");
  gray "ior ignored" (0.25 *. k) (shadow "rgbt <1,1,1,.5>" "interior { ior 1.5 }");
  gray "no_shadow" k (shadow "rgb 1" "no_shadow");
  (* path inside the sphere: 1 unit; fade 1/(1+(1/0.5)^2) = 0.2 *)
  gray ~eps:1e-4 "interior fade in shadow" (0.2 *. k)
    (shadow "rgbt 1" "interior { fade_distance 0.5 fade_power 2 }")

let bg = "background { rgb <.2,.4,.6> }\n"
let tilted = "plane { <0, 0.8660254, -0.5>, -0.5 "

let reflection () =
  color "reflection {.1,.9} head-on" (0.02, 0.04, 0.06)
    (pixel (bg ^ "plane { z, 1 finish { reflection { 0.1, 0.9 } } }"));
  color "reflection {.1,.9} at 60" (0.1, 0.2, 0.3)
    (pixel (bg ^ tilted ^ "finish { reflection { 0.1, 0.9 } } }"));
  color "falloff 2 at 60" (0.06, 0.12, 0.18)
    (pixel (bg ^ tilted ^ "finish { reflection { 0.1, 0.9 falloff 2 } } }"));
  color "exponent 0.5" (0.02, 0.08, 0.18)
    (pixel (bg ^ "plane { z, 1 finish { reflection { 0.5 exponent 0.5 } } }"));
  color ~eps:1e-4 "reflection metallic head-on" (0.1, 0.1, 0.)
    (pixel (bg ^ "plane { z, 1 pigment { rgb <1,.5,0> } finish { ambient 0 diffuse 0 reflection { 0.5 metallic } } }"));
  color "white + reflection adds" (0.7 +. 0.1, 0.7 +. 0.2, 0.7 +. 0.3)
    (pixel (bg ^ "light_source { <0,0,-10>, rgb 1 }\nplane { z, 1 pigment { rgb 1 } finish { reflection 0.5 } }"));
  let fres tilt =
    let a = tilt *. Float.pi /. 180. in
    pixel
      (Printf.sprintf
         "background { rgb 1 }\nplane { <0, %f, %f>, %f finish { reflection { 0, 1 fresnel on } } interior { ior 1.5 } }"
         (sin a) (-.cos a) (-.cos a))
  in
  gray ~eps:1e-4 "fresnel head-on" 0.04 (fres 0.);
  gray ~eps:1e-4 "fresnel 60" 0.0892 (fres 60.);
  gray ~eps:1e-4 "fresnel 80" 0.3877 (fres 80.);
  gray "fresnel without ior" 0.
    (pixel "background { rgb 1 }\nplane { z, 1 finish { reflection { 0, 1 fresnel on } } }")

let transparency () =
  let back = "plane { z, 2 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n" in
  let front pig = "light_source { <0,0,-10>, rgb 1 }\n" ^ back
                  ^ Printf.sprintf "plane { z, 1 pigment { %s } }\n" pig in
  color "rgbt over white" (0.85, 0.675, 0.5) (pixel (front "rgbt <1,.5,0,.5>"));
  color "rgbf over white" (0.85, 0.425, 0.) (pixel (front "rgbf <1,.5,0,.5>"));
  gray "rgbt 1 + phong 0.5 shows the highlight" 0.5
    (pixel "light_source { <0,0,-10>, rgb 1 }\nplane { z, 1 pigment { rgbt 1 } finish { phong 0.5 } }");
  (* legacy alpha: no #version *)
  let legacy =
    Whitted.pixel
      (compile ~raw:true
         ("light_source { <0,0,-10>, rgb 1 }\nplane { z, 1 pigment { rgbf <.5,.25,0,.5> } }\n"))
      ~width:1 ~height:1 0 0
  in
  close "legacy alpha" 0.2625 legacy.r;
  (* seen from inside glass (a half-space, background 0.25): on total
     internal reflection POV-Ray adds the reflected ray alone, whatever
     the finish's reflection says; at normal incidence the finish's
     reflection is added to the transmitted light (values measured with
     povray 3.7: 0.25 in every TIR case, 0.2602 and 0.375 head-on) *)
  let inside look_at refl =
    pixel
      (Printf.sprintf
         "camera { location <0,-1,0> look_at %s angle 10 }\nbackground { rgb 0.25 }\n\
          plane { y, 0 pigment { rgbf 1 } finish { ambient 0 diffuse 0 %s } interior { ior 1.5 } }\n"
         look_at refl)
  in
  List.iter
    (fun refl -> gray ("TIR with " ^ refl) 0.25 (inside "<0,0,1.732>" refl))
    [ ""; "reflection { 0, 1 fresnel on }"; "reflection 0.5"; "reflection { 0.5 exponent 0.5 }";
      "reflection { rgb <1,0,0> }" ];
  (* interior fade over 2 units of a transmit-1 slab (fade_distance 1):
     fade_power 1 -> 1/3, fade_power 0 -> 1/2 for the eye; the light is
     not faded by fade_power 0 (measured in povray 3.7) *)
  let slab fp =
    Printf.sprintf
      "box { <-5,-5,-1>, <5,5,1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } \
       interior { fade_distance 1 fade_power %d } }\n" fp
  in
  let seen fp = pixel ("camera { orthographic location <0,0,-10> look_at 0 right x up y }\n\
                        background { rgb 1 }\n" ^ slab fp) in
  gray "fade_power 1 seen" (1. /. 3.) (seen 1);
  gray "fade_power 0 seen" 0.5 (seen 0);
  let lit fp =
    pixel ("camera { location <0,0,-10> look_at <0,0,5> }\nlight_source { <0,0,-100>, rgb 1 }\n\
            plane { z, 5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" ^ slab fp)
  in
  (* the eye sees the plane through the slab too: shadow x eye fade *)
  gray "fade_power 0: light unfaded" 0.5 (lit 0);
  gray ~eps:2e-4 "head-on, fresnel" 0.2602 (inside "<0,0,0.3>" "reflection { 0, 1 fresnel on }");
  gray "head-on, reflection 0.5" 0.375 (inside "<0,0,0.3>" "reflection 0.5")

(* Focal blur: a plane in the focal plane stays sharp (every lens ray
   meets the same point), an edge far behind it is spread over the lens's
   image: the pixel on the edge becomes the mean of both sides. *)
let focal_blur () =
  let cam focal = Printf.sprintf
      "camera { location 0 look_at z angle 5 aperture 0.4 blur_samples 64 focal_point <0,0,%g> }\n"
      focal in
  let edge z = Printf.sprintf
      "plane { z, %g pigment { checker rgb 0, rgb 1 scale 100 translate <0,50,-1e-3> } \
       finish { ambient 1 diffuse 0 } }\n" z in
  let sharp = pixel ~w:2 ~h:1 ~x:0 (cam 10. ^ edge 10.) and pin = pixel ~w:2 ~h:1 ~x:0 (edge 10.) in
  if pin.r > 0.01 && pin.r < 0.99 then Alcotest.failf "the pinhole pixel is on the edge: %g" pin.r;
  color "in focus = pinhole" (pin.r, pin.g, pin.b) sharp;
  (* the lens ray from (lx, ly) x radius 0.1 through the focal point
     (x_f, 0, 1) meets z = 10 at x = 10 x_f - 0.9 lx: the pinhole's side
     (x < 0) is seen from the part of the unit disc where lx > -0.242,
     0.6525 of it *)
  let xf = -0.25 *. 2. *. Float.tan (2.5 *. Float.pi /. 180.) in
  let c = -10. *. xf /. 0.9 in
  let cap = (Float.acos c -. (c *. Float.sqrt (1. -. (c *. c)))) /. Float.pi in
  let expect = (pin.r *. (1. -. cap)) +. ((1. -. pin.r) *. cap) in
  (* the pixels of a column see the same share, each with the lens points
     turned its own way: unbiased in the mean, and spread less than
     random points would be (0.06 for 64 of them) *)
  let column samples variance =
    let s = Scn.compile (Printf.sprintf "camera { location 0 look_at z angle 5 aperture 0.4 \
        blur_samples %d variance %s focal_point <0,0,1> }\n" samples variance ^ edge 10.) in
    let v = Array.init 100 (fun y -> (Whitted.pixel s ~width:2 ~height:100 0 y).r) in
    let mean = Array.fold_left ( +. ) 0. v /. 100. in
    let sd = Float.sqrt (Array.fold_left (fun a x -> a +. ((x -. mean) *. (x -. mean))) 0. v /. 100.) in
    (mean, sd)
  in
  List.iter
    (fun (samples, variance, mean_eps, sd_max) ->
      let mean, sd = column samples variance in
      if Float.abs (mean -. expect) > mean_eps || sd > sd_max then
        Alcotest.failf "blur_samples %d variance %s: mean %g (the lens's share %g), spread %g (at most %g)"
          samples variance mean expect sd sd_max)
    [ (* every ray traced *)
      (64, "0", 0.01, 0.04);
      (* POV-Ray's test stops after about 49 rays here (a 0/1 edge's
         variance of the mean is under 1/128's threshold from 43 rays) *)
      (64, "1/128", 0.015, 0.05);
      (* one batch of 7, whatever the test says *)
      (7, "1/128", 0.03, 0.1) ]

(* An object without a texture takes the #default texture in force where
   it is placed (povray 3.7 renders bwstripe.pov this way): 0.5 x ambient
   0.55; a CSG child without one inherits its parent's; before any
   #default, the built-in black (known difference: an object directly
   followed by a #default takes the new one; here a sphere stands between). *)
let default_texture () =
  let d = "#default { texture { pigment { rgb 0.5 } finish { ambient 0.55 diffuse 0 } } }\n" in
  gray "#default texture" 0.275 (pixel (d ^ "plane { z, 1 }"));
  gray "inherited through a union" 0.275 (pixel (d ^ "union { plane { z, 1 } sphere { <0,0,5>, 1 } }"));
  gray "a parent's texture wins" 1.
    (pixel (d ^ "union { plane { z, 1 } pigment { rgb 1 } finish { ambient 1 } }"));
  gray "before #default" 0. (pixel ("plane { z, 1 }\nsphere { <0,0,-10>, 1 }\n" ^ d));
  (* a normal written after #default { normal { ... } } starts from the
     default normal, as POV-Ray copies it: its amount, transformations and
     turbulence (values measured with povray 3.7) *)
  let bumpy d =
    pixel
      ("light_source { <5, 5, -10>, rgb 1 }\n#default { " ^ d ^ " finish { phong 0.8 phong_size 20 } }\n\
        plane { z, 1 pigment { rgb 1 } normal { marble turbulence 0.5 scale 0.7 } }")
  in
  gray ~eps:2e-5 "no default normal" 0.64176 (bumpy "");
  gray ~eps:2e-5 "default bump_size" 0.67512 (bumpy "normal { bump_size 1.5 }");
  gray ~eps:2e-5 "default bump_size and scale" 0.58384 (bumpy "normal { bump_size 1.5 scale 3 }")

(* The slope of a normal pattern, as povray 3.7 measures it: a plane lit
   head-on with normal { gradient x, 1 }: 0.99124 on the ramps (tilt 2/15),
   0.20097 just before each jump (x = 0.985) and 0.17383 just after
   (x = 1.005), where its sampling tetrahedron of radius 0.02 straddles
   the jump. *)
let normal_slope () =
  let at x =
    pixel
      (Printf.sprintf
         "camera { orthographic location <%g,0,-10> look_at <%g,0,0> right 0.001*x up 0.001*y }\n\
          light_source { <%g,0,-1000>, rgb 1 parallel point_at <%g,0,0> }\n\
          plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { gradient x, 1 } }\n"
         x x x x)
  in
  gray "ramp" 0.99124 (at 0.5);
  gray "before the jump" 0.20097 (at 0.985);
  gray "after the jump" 0.17383 (at 1.005)

(* POV-Ray's ripples and waves normals (normal.cpp): in pattern space,
   the unit normal plus, over the wave sources c (Pattern.waves),
   amount sin(d frequency f + phase) / (f n d) (p - c) at the distance d
   (ripples: f = 1; waves: the source's frequency), the sine in turns
   (cycloidal), normalised back in world space *)
let ripples_normal () =
  let at text (px, py, pz) =
    let nm = Option.get (Scn.compile ("camera { normal { " ^ text ^ " } }")).camera.normal in
    let p = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
    Vec3.set p px py pz;
    Vec3.set n 0. 1. 0.;
    Normal.perturb_m nm p n out;
    (out.mx, out.my, out.mz)
  in
  let single = Floats.single in
  let expect ?(scale = 1.) ?(freq = 1.) ?(phase = 0.) ripples amount (px, py, pz) =
    (* pattern space: the point divided by the scale; the normal too, made unit *)
    let qx = px /. scale and qy = py /. scale and qz = pz /. scale in
    let x = ref 0. and y = ref 1. and z = ref 0. in
    let wv = Pattern.waves () in
    for i = 0 to wv.count - 1 do
      let c k = Float.Array.get wv.src ((3 * i) + k) in
      let f = if ripples then 1. else Float.Array.get wv.freq i in
      let vx = qx -. c 0 and vy = qy -. c 1 and vz = qz -. c 2 in
      let d = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
      let k = single amount *. Pattern.cycloidal ((d *. single freq *. f) +. single phase) /. f /. (d *. float_of_int wv.count) in
      x := !x +. (k *. vx);
      y := !y +. (k *. vy);
      z := !z +. (k *. vz)
    done;
    (* back to world space: a normal scales by 1 / scale, uniformly here *)
    let l = Float.sqrt ((!x *. !x) +. (!y *. !y) +. (!z *. !z)) in
    (!x /. l, !y /. l, !z /. l)
  in
  let check msg (ex, ey, ez) (x, y, z) = Scn.check_floats ~eps:1e-12 msg [ ex; ey; ez ] [ x; y; z ] in
  Alcotest.(check int) "ten sources" 10 (Pattern.waves ()).count;
  List.iter
    (fun p ->
      check "ripples 0.6" (expect true 0.6 p) (at "ripples 0.6" p);
      check "waves 0.8" (expect false 0.8 p) (at "waves 0.8" p);
      check "ripples, scale 0.3" (expect ~scale:0.3 true 0.5 p) (at "ripples 0.5 scale 0.3" p);
      check "ripples, frequency 2 phase 0.3" (expect ~freq:2. ~phase:0.3 true 1. p)
        (at "ripples 1 frequency 2 phase 0.3" p);
      check "waves, frequency 1.7 phase 0.2" (expect ~freq:1.7 ~phase:0.2 false 0.7 p)
        (at "waves 0.7 frequency 1.7 phase 0.2" p))
    [ (0.3, 0., 0.7); (-2.1, 0.5, 1.3); (5., 0., -4.) ]

(* normal_map, average and block lists of normals, as povray 3.7 shades
   them (probes: a plane lit by a parallel light towards [light], one
   sample at (x, 0.25), +FN16 File_Gamma=1.0): the entries' unit normals
   weighted, summed and normalised *)
let normal_maps () =
  let at ?(x = 0.5) light n =
    pixel
      (Printf.sprintf
         "camera { orthographic location <%g,0.25,-10> look_at <%g,0.25,0> right 0.001*x up 0.001*y }\n\
          light_source { <0,0,0>, rgb 1 parallel point_at %s }\n\
          plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { %s } }\n"
         x x light n)
  in
  let mirror = "gradient y normal_map { [0 gradient x, 1] [1 gradient x, -1] }" in
  (* weights 0.75 and 0.25 of (-s, 0, c) and (s, 0, c): c / |(-s/2, 0, c)| head-on *)
  gray "blend of a normal and its mirror, head-on" 0.99779 (at "<0,0,1>" mirror);
  gray "blend, lit from +x" 0.92219 (at "<1,0,2>" mirror);
  gray "blend, lit from +y" 0.89244 (at "<0,1,2>" mirror);
  gray "blend, the map scaled" 0.99504 (at "<0,0,1>" (mirror ^ " scale 2"));
  gray "blend, the map scaled, from +x" 0.93449 (at "<1,0,2>" (mirror ^ " scale 2"));
  let avg = "average normal_map { [1 gradient x, 1] [1 gradient x, -1] }" in
  gray "average of a normal and its mirror: flat" 1. (at "<0,0,1>" avg);
  gray "average flat, lit from +x" 0.89442 (at "<1,0,2>" avg);
  let w13 = "average normal_map { [1 gradient x, 1] [3 gradient y, 1] }" in
  gray "average weighted 1:3, head-on" 0.99449 (at "<0,0,1>" w13);
  gray "average weighted 1:3, from +x" 0.90433 (at "<1,0,2>" w13);
  gray "average weighted 1:3, from +y" 0.93397 (at "<0,1,2>" w13);
  (* an entry without a weight weighs 1 (textures/normals/normavg.pov) *)
  let w13' = "average normal_map { [gradient x, 1] [3 gradient y, 1] }" in
  gray "a missing weight is 1 (+x)" 0.90433 (at "<1,0,2>" w13');
  gray "a missing weight is 1 (+y)" 0.93397 (at "<0,1,2>" w13');
  let neg = "average normal_map { [1 gradient x, 1] [-2 gradient y, 1] }" in
  gray "negative weights (+x)" 0.8 (at "<1,0,2>" neg);
  gray "negative weights (+y)" 0.97144 (at "<0,1,2>" neg);
  gray "negative weights (head-on)" 0.95831 (at "<0,0,1>" neg);
  (* an entry's rotation is its own; the map's applies to all *)
  let turned = "gradient y normal_map { [0 gradient x, 1 rotate 90*z] [1 gradient x, -1] }" in
  gray "an entry keeps its rotation (+x)" 0.87468 (at "<1,0,2>" turned);
  gray "an entry keeps its rotation (+y)" 0.93397 (at "<0,1,2>" turned);
  gray "the map's rotation moves all (+x)" 0.86079 (at "<1,0,2>" (turned ^ " rotate 90*z"));
  gray "the map's rotation moves all (+y)" 0.86079 (at "<0,1,2>" (turned ^ " rotate 90*z"));
  (* a declared normal as an entry is the same normal *)
  let declared =
    pixel
      "#declare N = normal { gradient x, 1 rotate 90*z }\n\
       camera { orthographic location <0.5,0.25,-10> look_at <0.5,0.25,0> right 0.001*x up 0.001*y }\n\
       light_source { <0,0,0>, rgb 1 parallel point_at <1,0,2> }\n\
       plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 }\n\
         normal { gradient y normal_map { [0 N] [1 gradient x, -1] } } }\n"
  in
  gray "a declared entry" 0.87468 declared;
  let cells = "checker normal { gradient x, 1 } normal { gradient x, 1 rotate 90*z }" in
  gray "checker's first cell (+x)" 0.94569 (at "<1,0,2>" cells);
  gray "checker's second cell (+x)" 0.88658 (at ~x:1.5 "<1,0,2>" cells);
  gray "checker's second cell (+y)" 0.94569 (at ~x:1.5 "<0,1,2>" cells)

(* texture { average texture_map { ... } }: each entry shaded (its own
   normal and finish), the colours weighted over the weights' sum; the
   values POV-Ray 3.7 renders (16-bit, file gamma 1) *)
let average_textures () =
  let at light t =
    pixel
      (Printf.sprintf
         "camera { orthographic location <0.5,0.25,-10> look_at <0.5,0.25,0> right 0.001*x up 0.001*y }\n\
          light_source { <0,0,0>, rgb 1 parallel point_at %s }\n\
          plane { z, 0 texture { %s } }\n"
         light t)
  in
  color ~eps:1e-4 "weights 1 and 3, finishes their own" (0.25, 0., 0.37501)
    (at "<0,0,1>"
       "average texture_map { [1 pigment { rgb <1,0,0> } finish { ambient 0 diffuse 1 }] \
        [3 pigment { rgb <0,0,1> } finish { ambient 0 diffuse 0.5 }] }");
  gray ~eps:1e-4 "a normal in one entry, no weights (1 each)" 0.92006
    (at "<1,0,2>"
       "average texture_map { [pigment { rgb 1 } normal { gradient x, 1 } finish { ambient 0 diffuse 1 }] \
        [pigment { rgb 1 } finish { ambient 0 diffuse 1 }] }");
  color ~eps:1e-4 "weights 2 and 1, ambient, the average scaled" (0.50799, 0.40307, 0.29815)
    (at "<1,0,2>"
       "average texture_map { [2 pigment { rgb <1,0.5,0> } normal { gradient x, 1 } finish { ambient 0.1 diffuse 0.7 }] \
        [1 pigment { rgb <0,0.5,1> } finish { ambient 0 diffuse 1 }] } scale 2");
  Scn.check_message "sphere { 0, 1 texture { average } }" "an average texture needs a texture_map";
  Scn.check_message "sphere { 0, 1 texture { average texture_map { [1 pigment { rgb 1 }] [-1 pigment { rgb 0 }] } } }"
    "the weights of an average's texture_map must not sum to 0"

let mirrors = "plane { z, 1 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 0.5 } }\n\
               plane { z, -1 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 0.5 } }\n"

let levels () =
  List.iter
    (fun (n, v) ->
      gray (Printf.sprintf "max_trace_level %d" n) v
        (pixel (Printf.sprintf "global_settings { max_trace_level %d }\n" n ^ mirrors)))
    [ (1, 0.1); (2, 0.15); (3, 0.175); (5, 0.19375) ];
  gray ~eps:1e-5 "adc bailout default" 0.19922
    (pixel ("global_settings { max_trace_level 100 }\n" ^ mirrors));
  gray ~eps:1e-6 "adc bailout 0" 0.2
    (pixel ("global_settings { max_trace_level 100 adc_bailout 0 }\n" ^ mirrors));
  gray "mirror at level 1 returns black" 0.
    (pixel "background { rgb 1 }\nglobal_settings { max_trace_level 1 }\nplane { z, 1 finish { reflection 1 } }");
  let stack =
    String.concat ""
      (List.init 8 (fun i -> Printf.sprintf "plane { -z, %d pigment { rgbt 1 } }\n" (-(i + 1))))
  in
  gray "pure transmission uses no level" 1.
    (pixel ("background { rgb 1 }\nglobal_settings { max_trace_level 2 }\n" ^ stack));
  (* the camera is inside eight nested planes of ior 1.5 (POV-Ray starts
     camera rays inside the objects containing the camera): only leaving
     the last one refracts *)
  let nested =
    String.concat ""
      (List.init 8 (fun i -> Printf.sprintf "plane { z, %d pigment { rgbt 1 } interior { ior 1.5 } }\n" (i + 1)))
  in
  gray "camera inside nested media" 1.
    (pixel ("background { rgb 1 }\nglobal_settings { max_trace_level 2 }\n" ^ nested))

let layers () =
  (* top layer rgbt .5 red over white: top shading + 0.5 * bottom shading *)
  let src = "light_source { <0,0,-10>, rgb 1 }\n\
             plane { z, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt <1,0,0,.5> } } }" in
  color "two layers" (0.35 +. 0.35, 0.35, 0.35) (pixel src);
  let sky = "sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }\n" in
  gray ~eps:1e-4 "sky_sphere along +z" 0. (pixel sky);
  color "transparent sky shows the background" (0.6, 0.7, 0.8)
    (pixel "background { rgb <.2,.4,.6> }\nsky_sphere { pigment { rgbt <1,1,1,.5> } }");
  gray ~eps:1e-4 "sky_sphere up" 0.70711 (pixel ("camera { look_at <0, 1, 1> }\n" ^ sky))

(* conserve_energy: what a layer lets through is cut by what it reflects,
   (1 - reflectivity) per channel and at most 1, a reflectivity above 1
   taking light away; and a layer's reflection is not filtered by the
   layers above it. A plane at z = 1 over a white one (ambient 1) at z
   = 2, background <.2, .4, .6>; every value measured with povray 3.7
   (1x1, +FN16, File_Gamma 1), where a PNG's negative channel reads 0 *)
let conserve_energy () =
  let back = bg ^ "plane { z, 2 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n" in
  let front pig fin =
    pixel
      (back
      ^ Printf.sprintf "plane { z, 1 pigment { %s } finish { ambient 0 diffuse 0 %s } interior { ior 1 } }" pig fin)
  in
  color "reflection 0.5, not conserved" (1.1, 1.2, 1.3) (front "rgbf 1" "reflection 0.5");
  color "reflection 0.5" (0.6, 0.7, 0.8) (front "rgbf 1" "reflection 0.5 conserve_energy");
  color "reflection 0.5, filter" (0.6, 0.45, 0.3) (front "rgbf <1,.5,0,1>" "reflection 0.5 conserve_energy");
  color "reflection 0.5, transmit" (0.4, 0.5, 0.6) (front "rgbt <1,.5,0,.6>" "reflection 0.5 conserve_energy");
  color "coloured reflection" (0.2, 0.7, 1.0) (front "rgbf 1" "reflection { rgb <1,.5,0> } conserve_energy");
  color "coloured reflection, filter" (0.2, 0.45, 0.) (front "rgbf <1,.5,0,1>" "reflection { rgb <1,.5,0> } conserve_energy");
  color "variable reflection (0.1 head-on)" (0.92, 0.49, 0.06)
    (front "rgbf <1,.5,0,1>" "reflection { 0.1, 0.9 } conserve_energy");
  color "metallic reflection, tinted by the pigment" (0.6, 0.475, 0.)
    (front "rgbf <1,.5,0,1>" "reflection { 0.5 metallic } conserve_energy");
  color "metallic reflection, transmit" (0.4, 0.55, 0.6)
    (front "rgbt <1,.5,0,.6>" "reflection { 0.5 metallic } conserve_energy");
  (* 1 - 1.5 = -0.5: the light behind taken away (red -0.2, which the
     PNG shows as 0) *)
  let r = front "rgbf <1,.5,0,1>" "reflection 1.5 conserve_energy" in
  color "reflection above 1" (-0.2, 0.35, 0.9) r;
  (* layered: the top layer (written last) rgbt 1, reflection 0.5; the
     bottom one rgbf <1,.5,0,1>, reflection 0.2: the top lets through
     half, the bottom's filter and (with conserve_energy) 0.8 of it; the
     bottom's reflection is added in full *)
  let layered bottom_ce =
    pixel
      (back
      ^ Printf.sprintf
          "plane { z, 1 texture { pigment { rgbf <1,.5,0,1> } finish { ambient 0 diffuse 0 reflection 0.2 %s } }\n\
           texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 reflection 0.5 conserve_energy } } }"
          bottom_ce)
  in
  color "layered, both conserving" (0.54, 0.48, 0.42) (layered "conserve_energy");
  color "layered, the top conserving" (0.64, 0.53, 0.42) (layered "");
  (* the layers above do not filter a layer's reflection, with or without
     conserve_energy: a mirror (0.5) under rgbt 0.5 black, or under an
     rgbf 0.5 green, reflects 0.5 of the background *)
  let under top =
    pixel
      (back
      ^ Printf.sprintf
          "plane { z, 1 texture { pigment { rgb <1,.5,0> } finish { ambient 0 diffuse 0 reflection 0.5 } }\n\
           texture { pigment { %s } finish { ambient 0 diffuse 0 } } }"
          top)
  in
  color "a mirror under rgbt 0.5" (0.1, 0.2, 0.3) (under "rgbt <0,0,0,.5>");
  color "a mirror under rgbf 0.5 green" (0.1, 0.2, 0.3) (under "rgbf <0,1,0,.5>");
  color "lit layers, reflections in full" (0.12, 0.465, 0.36)
    (pixel
       (back
       ^ "light_source { <0,0,-10>, rgb 1 }\n\
          plane { z, 1 texture { pigment { rgb <1,.5,0> } finish { ambient 0 diffuse 0.5 reflection 0.5 } }\n\
          texture { pigment { rgbf <0,1,0,.5> } finish { ambient 0 diffuse 0.2 reflection 0.1 } } }"));
  (* seen from inside glass: on total internal reflection the finish's
     reflection is not traced, and nothing passes: the reflected ray
     alone, as without conserve_energy (0.25); head-on 0.25 too *)
  let inside look_at =
    pixel
      (Printf.sprintf
         "camera { location <0,-1,0> look_at %s angle 10 }\nbackground { rgb 0.25 }\n\
          plane { y, 0 pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.5 conserve_energy } interior { ior 1.5 } }\n"
         look_at)
  in
  gray "inside glass, total internal reflection" 0.25 (inside "<0,0,1.732>");
  gray "inside glass, head-on" 0.25 (inside "<0,0,0.3>")

let declared () =
  color "declared colour map" (0.75, 0., 0.25)
    (pixel "#declare CM = color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }\n\
            plane { z, 1 pigment { gradient x color_map { CM } translate -x*0.25 } finish { ambient 1 diffuse 0 } }");
  color "layered texture identifier keeps its layers" (0.7, 0.35, 0.35)
    (pixel "light_source { <0,0,-10>, rgb 1 }\n\
            #declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt <1,0,0,.5> } }\n\
            plane { z, 1 texture { T } }");
  color "old-form colour map entry" (0.75, 0., 0.25)
    (pixel "plane { z, 1 pigment { gradient x color_map { [0, 1 color rgb <1,0,0> color rgb <0,0,1>] }\n\
            translate -x*0.25 } finish { ambient 1 diffuse 0 } }");
  gray "declared sky_sphere" 0.5
    (pixel "#declare S = sky_sphere { pigment { rgb 0.5 } }\nsky_sphere { S }");
  let s =
    compile "#declare M = material { texture { pigment { rgbt 1 } } interior { ior 1.5 } }\n\
             sphere { 0, 1 material { M } }"
  in
  close "material interior" 1.5 s.objects.(0).interior.ior;
  close "material texture" 1. (Pigment.eval (List.hd s.objects.(0).texture).pigment Vec3.zero).transmit

(* Minor words per camera ray of a 64x48 one-domain render as [camlray
   render] runs it ([Render.image_into]), the second of two (the first
   makes the domain's scratch) *)
let words_per_ray s =
  let width = 64 and height = 48 in
  let pixel = Whitted.pixel_into s ~width ~height in
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  let before = Gc.minor_words () in
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  (Gc.minor_words () -. before) /. Float.of_int (width * height)

(* The hot path allocates nothing in the common case: solid pigments, a
   plain checker, point lights, reflection, spheres of the flat array,
   planes, boxes, meshes, a difference, and a glass intersection casting
   shadows (crossings that a CSG rule rejects, and crossings a shadow
   passes through). Minor words per camera ray over a
   one-domain render as [camlray render] runs it ([Render.image_into]):
   none, with shadows or without. *)
let allocation () =
  let words light =
    let s =
      Scn.compile
        (Printf.sprintf
           "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
            light_source { <-4, 6, -5>, rgb 1 %s }\n\
            plane { y, 0 pigment { checker rgb 1, rgb <0.1, 0.2, 0.5> } finish { phong 0.3 } }\n\
            sphere { <-1, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { specular 0.5 } }\n\
            sphere { <1.2, 0.8, 0.5>, 0.8 pigment { rgb 0.9 } finish { reflection 0.6 } }\n\
            box { <-0.5, 0, -2>, <0.5, 0.6, -1.4> pigment { rgb <0.2, 0.7, 0.3> } }\n\
            mesh { triangle { <1, 0, -2>, <2, 0, -2>, <1.5, 1, -1.8> } pigment { rgb 0.5 } }\n\
            difference { box { <-2.6, 0, -1.2>, <-1.8, 0.8, -0.4> } sphere { <-2.2, 0.8, -1.2>, 0.5 }\n\
              pigment { rgb <0.7, 0.6, 0.2> } }\n\
            intersection { sphere { <2.2, 0.5, -1>, 0.5 } sphere { <2.6, 0.5, -1>, 0.5 }\n\
              pigment { rgbf <0.8, 1, 0.8, 0.8> } interior { ior 1.3 } }"
           light)
    in
    words_per_ray s
  in
  let none = words "shadowless" and shadows = words "" in
  (* the tiles and their sums: a few words per 16x16 tile *)
  if none > 0.1 then Alcotest.failf "%.2f words per camera ray without shadows (at most 0.1)" none;
  (* one light: a shadow ray per opaque hit, reflections' hits included *)
  if shadows > 0.1 then Alcotest.failf "%.2f words per camera ray with one light (at most 0.1)" shadows;
  (* area lights: 16 shadow rays a hit averaged adaptively, square and
     oriented disc *)
  let area = words "area_light <2, 0, 0>, <0, 0, 2>, 4, 4 adaptive 1"
  and disc = words "area_light <2, 0, 0>, <0, 2, 0>, 5, 5 circular orient" in
  if area > 0.1 then Alcotest.failf "%.2f words per camera ray with an area light (at most 0.1)" area;
  List.iter
    (fun (what, light) ->
      let w = words light in
      if w > 0.1 then Alcotest.failf "%.2f words per camera ray with a %s light (at most 0.1)" w what)
    [ ("spot", "spotlight point_at <0, 0, 0> radius 15 falloff 25 tightness 10");
      ("parallel", "parallel point_at <0, 0, 0>");
      ("fading", "fade_distance 4 fade_power 2");
      ("per-sample area", "area_light <2, 0, 0>, <0, 0, 2>, 3, 3 area_illumination on") ];
  if disc > 0.1 then Alcotest.failf "%.2f words per camera ray with a circular area light (at most 0.1)" disc;
  (* the curved solids that skip segments by their boxes: a lathe, a sor
     and a prism of each sweep (a box test written with a local function
     once cost 98 words a camera ray, the prism's inside test, its floats
     boxed, 0.1 more) *)
  let shapes =
    Scn.compile
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       light_source { <-4, 6, -5>, rgb 1 }\n\
       plane { y, 0 pigment { rgb 0.8 } }\n\
       lathe { cubic_spline 6, <0.2, -0.1>, <0.6, 0>, <0.9, 0.6>, <0.4, 1.2>, <0.5, 1.6>, <0.6, 1.8> pigment { rgb 0.7 } translate -1.8*x }\n\
       sor { 5, <0, -0.5>, <0.8, 0>, <1, 0.6>, <0.4, 1.4>, <0.5, 2> pigment { rgb 0.6 } }\n\
       prism { cubic_spline linear_sweep 0, 0.6, 6, <-0.5, -1>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <0.5, -0.5>, <0.5, 0.5> pigment { rgb 0.5 } translate <1.8, 0, -0.5> }\n\
       prism { linear_spline conic_sweep 1, 0.4, 4, <-0.5, -0.5>, <0.5, -0.5>, <0, 0.5>, <-0.5, -0.5> pigment { rgb 0.4 } rotate 180*x translate <1.8, 1.2, 1> }"
  in
  let w = words_per_ray shapes in
  if w > 0.1 then Alcotest.failf "%.2f words per camera ray on lathes, sors and prisms (at most 0.1)" w

(* The same with textures as POV-Ray scenes write them: pattern pigments
   through colour maps, pigment maps and blocks (with turbulence and
   waves), normal perturbation (normal_map, a nested average, a checker
   of normals), a metallic finish, a texture map, shadows
   through patterned transparent spheres, a fading interior seen through
   and casting shadows, and a sky_sphere, for camera
   rays that end on the sky and rays that start inside an object (the
   camera in a big sphere). *)
let allocation_textures () =
  let words camera =
  let s =
    Scn.compile
      (camera ^ "\n\
       light_source { <-4, 6, -5>, rgb 1 }\n\
       sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }\n\
       sphere { 0, 100 hollow pigment { rgbt 1 } }\n\
       plane { y, 0 pigment { hexagon rgb 1, rgb <0.2, 0.3, 0.5>, rgb <0.7, 0.2, 0.1> scale 0.5 }\n\
         normal { gradient x normal_map { [0 bumps 0.4 scale 0.3]\n\
           [1 average normal_map { [1 leopard 0.5 scale 0.2] [2 dents 0.3] }] } } }\n\
       sphere { <-1, 1, 0>, 1 pigment { bozo turbulence 0.5 octaves 4 color_map { [0 rgb 1] [1 rgb <0.8, 0.2, 0.1>] } }\n\
         normal { ripples 0.5 } finish { specular 0.5 } }\n\
       sphere { <1.2, 0.8, 0.5>, 0.8 pigment { granite pigment_map { [0 rgb 0.9] [1 onion color_map { [0 rgb 0] [1 rgb 1] }] } }\n\
         finish { reflection 0.4 metallic } }\n\
       box { <-0.5, 0, -2>, <0.5, 0.6, -1.4> pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.1> scale 0.05 }\n\
         normal { checker normal { dents 0.5 scale 0.1 } normal { onion 0.3 } scale 0.2 } }\n\
       sphere { <2, 0.4, -1.5>, 0.4 pigment { marble sine_wave frequency 3 turbulence 0.3\n\
         color_map { [0 rgb 1] [0.5 rgb <0.3, 0.5, 0.2>] [1 rgb 0] } } normal { wrinkles 0.6 } }\n\
       sphere { <-2.2, 0.6, -1>, 0.6 texture { gradient x texture_map {\n\
         [0 pigment { rgbf <1, 0.2, 0.2, 0.7> }] [1 pigment { rgb <0.2, 0.2, 1> } finish { phong 1 }] } scale 0.4 } }\n\
       sphere { <1, 0.5, -2.8>, 0.5 pigment { checker rgbf <1, 1, 1, 0.8>, rgbt <0.5, 1, 0.5, 0.6> scale 0.3 } }\n\
       sphere { <2.6, 1.4, 1>, 0.7 texture { average texture_map {\n\
         [1 pigment { rgbf <1, 0.5, 0.2, 0.5> } normal { leopard 0.4 scale 0.1 }] [2 pigment { rgb <0.2, 0.6, 0.3> } finish { phong 1 }] } } }\n\
       sphere { <-0.3, 0.45, -3.2>, 0.45 pigment { rgbf <0.9, 0.9, 1, 0.9> }\n\
         interior { ior 1.2 fade_distance 0.4 fade_power 2 fade_color <0.2, 0.4, 0.9> } }\n\
       box { <-1.8, 0, -3.6>, <-1, 0.8, -2.8> texture { uv_mapping pigment { rgb 0.8 }\n\
         normal { gradient x normal_map { [0 quilted 0.5 scale 0.1] [1 uv_mapping bumps 0.3 scale 0.1] } } } rotate y*20 }")
  in
  words_per_ray s
  in
  let plain = words "camera { location <0, 2, -6> look_at <0, 0.8, 0> }" in
  if plain > 0.1 then
    Alcotest.failf "%.2f words per camera ray with patterns, normals (uv-mapped too), texture maps and a sky (at most 0.1)" plain;
  (* a camera normal turning every ray *)
  let bent = words "camera { location <0, 2, -6> look_at <0, 0.8, 0> normal { onion 0.3 scale 0.2 } }" in
  if bent > 0.1 then Alcotest.failf "%.2f words per camera ray with a camera normal (at most 0.1)" bent;
  (* and through a lens: 8 rays a pixel *)
  let blur =
    words "camera { location <0, 2, -6> look_at <0, 0.8, 0> aperture 0.4 focal_point <0, 1, 0> blur_samples 8 }"
  in
  if blur > 0.1 then Alcotest.failf "%.2f words per pixel with focal blur (at most 0.1)" blur

(* The same in the air and in solids with media: a ground fog and an
   atmosphere lit by a spotlight (POV-Ray's lit and unlit intervals, its
   method-3 splitting), a sphere of scattering, emitting turbulent media
   sampled by method 2, shadow rays through both, a rainbow, a
   superellipsoid (its root bracketing) and a slope-mapped normal (each
   of these once cost 3 to 180 words a camera ray: floats passed to
   functions that were not inlined, local closures, tuples) *)
let allocation_media () =
  let s =
    Scn.compile
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       light_source { <-4, 6, -5>, rgb 1 spotlight point_at <0, 0, 0> radius 12 falloff 20 media_attenuation on }\n\
       light_source { <4, 5, -5>, rgb 0.5 }\n\
       fog { fog_type 2 distance 8 color rgb <0.6, 0.6, 0.7> fog_offset 0.5 fog_alt 1 up y }\n\
       media { scattering { 1, rgb 0.02 } intervals 3 samples 2 method 3 }\n\
       rainbow { angle 42.5 width 5 distance 1e3 direction <-0.2, -0.2, 1> jitter 0.01\n\
         color_map { [0 rgbt <1, 0, 0, 0.5>] [0.5 rgbt <0, 1, 0, 0.5>] [1 rgbt <0, 0, 1, 0.5>] } }\n\
       plane { y, 0 pigment { rgb 0.8 } normal { marble 0.5 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } } }\n\
       sphere { <-1, 1, 0>, 1 pigment { rgbt 1 } hollow interior { media {\n\
         scattering { 2, rgb <0.5, 0.4, 0.3> } emission rgb 0.1 absorption 0.2 method 2 intervals 2 samples 4\n\
         density { bozo turbulence 0.5 color_map { [0 rgb 0] [1 rgb 1] } } } } }\n\
       superellipsoid { <0.3, 0.6> pigment { rgb <0.8, 0.3, 0.2> } scale 0.7 translate <1.4, 0.7, 0> }"
  in
  let w = words_per_ray s in
  if w > 0.1 then
    Alcotest.failf "%.2f words per camera ray with fog, media, a rainbow and a superellipsoid (at most 0.1)" w

(* POV-Ray's own scenes' corners: an object pattern of text, a crackle
   normal, an isosurface of POV-Ray's internal functions (f_rounded_box,
   f_ridged_mf), a height field cut by a sphere, and glass inside glass
   (rays leaving a medium that is not the last entered): 160 words a
   camera ray before, mostly local closures (POV-Ray's benchmark.pov:
   12,345) *)
let allocation_corners () =
  let font = "/usr/share/povray-3.7/include/timrom.ttf" in
  let text =
    if Sys.file_exists font then
      Printf.sprintf "object { text { ttf \"%s\" \"ab\" 1, 0 scale 2 translate <-1, -0.3, -2> } rgb 1, rgb <0.8, 0.2, 0.1> }" font
    else "rgb 1"
  in
  let s =
    Scn.compile
      ("#declare RB = function { internal(60) }\n\
        #declare RMF = function { internal(59) }\n\
        camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
        light_source { <-4, 6, -5>, rgb 1 }\n\
        plane { y, 0 pigment { " ^ text ^ " } normal { crackle 0.5 turbulence 0.2 scale 0.3 } }\n\
        isosurface { function { RB(x, y, z, 0.05, 0.5, 0.5, 0.5) + 0.02 * RMF(x * 4, y * 4, z * 4, 0.5, 2, 3, 1, 2, 0) }\n\
          contained_by { box { -0.6, 0.6 } } max_gradient 4 pigment { rgb <0.3, 0.6, 0.9> } translate <-1.6, 0.6, 0> }\n\
        difference { height_field { function 32, 32 { 0.5 + 0.3 * sin(x * 8) * cos(y * 8) } translate <-0.5, 0, -0.5>\n\
          scale <1.2, 0.8, 1.2> } sphere { <0, 0.5, 0>, 0.3 } pigment { rgb <0.7, 0.7, 0.3> } translate <1.6, 0, 0> }\n\
        sphere { <0, 1, -1>, 0.8 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }\n\
        sphere { <0, 1, -1>, 0.4 pigment { rgbf <0.8, 1, 0.8, 0.9> } interior { ior 1.3 } }")
  in
  let w = words_per_ray s in
  if w > 0.1 then
    Alcotest.failf "%.2f words per camera ray with text, crackle, internal functions, a height field and nested glass (at most 0.1)" w

(* A block of 64 overlapping glass spheres, each its own interior (all
   with the same fields, as a #while loop makes them): rays inside two or
   three at once meet hundreds of (interior, media inside) pairs, where a
   cache of 16 pairs searched whole allocated 4.8 words a camera ray
   (lists entered and left made afresh; POV-Ray's stackertransp.pov the
   same) *)
let allocation_many_glasses () =
  let s =
    Scn.compile
      "camera { location <0, 0, -6> look_at <0, 0, 0> }\n\
       global_settings { max_trace_level 10 }\n\
       light_source { <-4, 6, -5>, rgb 1 }\n\
       plane { z, 4 pigment { checker rgb 0.2, rgb 0.9 } }\n\
       #declare I = 0;\n\
       #while (I < 64)\n\
         sphere { 0, 0.62 pigment { rgbf <0.9, 1, 1, 0.95> } interior { ior 1.5 }\n\
           translate <mod(I, 4) - 1.5, mod(div(I, 4), 4) - 1.5, div(I, 16) - 1.5> }\n\
         #declare I = I + 1;\n\
       #end"
  in
  let w = words_per_ray s in
  if w > 0.1 then Alcotest.failf "%.2f words per camera ray through 64 overlapping glass spheres (at most 0.1)" w

(* spline functions of the four kinds and a transform function called
   in pigment functions: members x to transmit and gray, a float-valued
   natural spline, parameters before, inside and past the entries (each
   call made a fresh array, the natural spline's coefficients at every
   call: 92.8 words a camera ray at 64x48 before they were evaluated in
   place) *)
let allocation_spline_functions () =
  let s =
    Scn.compile
      "camera { location <0, 0, -3> look_at 0 angle 40 }\n\
       #declare Pts = spline { -0.2, <0.1, 0.9, 0.3> 0.15, <0.8, 0.2, 0.5> 0.4, <0.3, 0.6, 0.9>\n\
         0.7, <0.9, 0.1, 0.2> 1.2, <0.2, 0.5, 0.7> }\n\
       #declare L = function { spline { linear_spline Pts } }\n\
       #declare Q = function { spline { quadratic_spline Pts } }\n\
       #declare C = function { spline { cubic_spline Pts } }\n\
       #declare N = function { spline { natural_spline Pts } }\n\
       #declare F = function { spline { natural_spline 0, 0.2 0.3, 0.9 0.6, 0.1 1, 0.7 } }\n\
       #declare T = function { transform { rotate 30*z scale 1.3 } }\n\
       #macro Row(Y, P) box { <-1, Y, 0>, <1, Y + 0.3, 0.1> pigment { P } finish { ambient 1 diffuse 0 } } #end\n\
       Row(-0.95, pigment { function { L(x * 0.75 + 0.5).x } color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } })\n\
       Row(-0.63, pigment { function { Q(x * 0.75 + 0.5).y * 0.5 + Q(x * 0.75 + 0.5).gray * 0.5 }\n\
         color_map { [0 rgb 0] [1 rgb <0, 1, 0.5>] } })\n\
       Row(-0.31, pigment { function { C(x * 0.75 + 0.5).z + C(x).t } color_map { [0 rgb 0] [1 rgb <0.5, 0, 1>] } })\n\
       Row(0.01, pigment { function { N(x * 0.75 + 0.5).gray + N(x).transmit } color_map { [0 rgb 0] [1 rgb 1] } })\n\
       Row(0.33, pigment { function { F(x * 0.6 + 0.5).u } color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } })\n\
       Row(0.65, pigment { function { abs(T(x, y, z).y) * 0.5 + T(x, y, z).gray * 0.2 }\n\
         color_map { [0 rgb 0] [1 rgb <0, 1, 1>] } })"
  in
  let w = words_per_ray s in
  if w > 0.1 then Alcotest.failf "%.2f words per camera ray with spline and transform functions (at most 0.1)" w

(* faked caustics on shadow rays through clear glass with a bumpy
   surface: the factor was a float returned from a function not inlined
   (0.4 words a camera ray on whitted-extra/caustics.pov) *)
let allocation_caustics () =
  let s =
    Scn.compile
      "camera { location <0, 3, -6> look_at <0, 0.5, 0> }\n\
       light_source { <2, 8, -3>, rgb 1 }\n\
       plane { y, 0 pigment { rgb 0.8 } }\n\
       sphere { <0, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } normal { bumps 0.4 scale 0.2 }\n\
         interior { ior 1.5 caustics 1 } }"
  in
  let w = words_per_ray s in
  if w > 0.1 then Alcotest.failf "%.2f words per camera ray with faked caustics (at most 0.1)" w

(* average pigment_map: the weighted mean of its entries *)
let average () =
  let flat pig = pixel (Printf.sprintf "plane { z, 1 pigment { %s } finish { ambient 1 diffuse 0 } }\n" pig) in
  color "weights 1 and 3" (0.25, 0., 0.75)
    (flat "average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1>] }");
  (* gradient x at x = 0 is 0: the first colour of each map; no weight: 1 *)
  color "weights left out count 1" (0.5, 0.5, 0.)
    (flat "average pigment_map { [gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb 1] }] \
           [gradient y color_map { [0 rgb <0, 1, 0>] [1 rgb 1] }] }");
  color "the same weights in other units" (0.25, 0., 0.75)
    (flat "average pigment_map { [0.5 rgb <1, 0, 0>] [1.5 rgb <0, 0, 1>] }")

(* POV-Ray's faked caustics: a shadow ray through a clear surface carries
   (1 + |cos|^(45 c)) of its light, cos to the surface's normal *)
let caustics () =
  let floor = light30 ^ plane "" in
  (* a clear disc across the light's way, facing the light (cos 1) or the
     camera (cos 0.866) *)
  let disc normal c =
    Printf.sprintf "disc { <0.2887, 0, 0.5>, %s, 0.1 pigment { rgbf 1 } interior { caustics %g } }\n" normal c
  in
  let toward = "<5, 0, -8.66025>" in
  gray "clear: the light passes" 0.61962 (pixel (floor ^ disc toward 0.));
  gray "caustics 1 square on: twice the light" (0.1 +. (2. *. 0.51962)) (pixel (floor ^ disc toward 1.));
  gray ~eps:1e-4 "caustics 1 at 30 degrees: 1 + 0.866^45" (0.1 +. ((1. +. (0.866025 ** 45.)) *. 0.51962))
    (pixel (floor ^ disc "z" 1.))

(* a pigment function called from a pattern inside interpolated maps: the
   same colour as the pattern written out (the maps' scratch colours are
   not overwritten by the inner evaluation) *)
let nested_pigment_function () =
  let scene inner =
    "#declare PF = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } }\n\
     plane { z, 1 pigment { gradient y pigment_map {\n\
       [0 rgb <0, 1, 0>]\n\
       [1 gradient z pigment_map {\n\
          [0 rgb 1]\n\
          [1 " ^ inner ^ " color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }] }] }\n\
       translate <0.3, 0.4, 0.45> }\n\
       finish { ambient 1 diffuse 0 } }\n"
  in
  let a = pixel (scene "function { PF(x, y, z).red }") and b = pixel (scene "gradient x") in
  color "as written out" (b.r, b.g, b.b) a;
  if b.r = b.g && b.g = b.b then Alcotest.fail "the maps were not all interpolated"

(* pigment { } and finish { } change what they are written over, as POV-Ray
   edits in place *)
let edits () =
  let tex = "#declare T = texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }\n\
             finish { ambient 0.5 diffuse 0 } }\n" in
  gray "a declared texture" 0.25 (pixel (tex ^ "plane { z, 1 texture { T pigment { translate 0.5*x } } }\n"));
  (* gradient x at x = 0 moved by 0.25: value 0.75, ambient 0.5 *)
  gray "its pigment moved, its finish kept" 0.375 (pixel (tex ^ "plane { z, 1 texture { T pigment { translate 0.25*x } } }\n"));
  gray "its finish changed, its pigment kept" (0.5 *. 0.75 +. 0.75 *. 0.1)
    (pixel (tex ^ "plane { z, 1 texture { T pigment { translate 0.25*x } finish { emission 0.1 } } }\n"));
  gray "an object's pigment { } changes its texture's" 0.375
    (pixel (tex ^ "plane { z, 1 texture { T } pigment { translate 0.25*x } }\n"));
  gray "a pigment written anew replaces it" 0.5 (pixel (tex ^ "plane { z, 1 texture { T pigment { rgb 1 } } }\n"))

(* POV-Ray's iridescence: a light's diffuse and highlights scaled per
   channel by 1 + a cos(2 pi t (|cos l| + |cos e|) / wavelength) *)
let irid () =
  let lit = "light_source { <0, 0, -10>, rgb 1 }\n" in
  let film a t = Printf.sprintf "plane { z, 1 pigment { rgb 1 } finish { irid { %g thickness %g } } }\n" a t in
  let k a t wl = 1. +. (a *. cos (2. *. Float.pi *. t *. 2. /. wl)) in
  (* head-on: both cosines 1; ambient 0.1 is not scaled, diffuse 0.6 is *)
  (* POV-Ray 3.7's default wavelengths are <0.70, 0.52, 0.48> (its
     SceneData; the documentation's <0.25, 0.18, 0.14> is not what it
     renders: 36 to 37 dB against its pictures, identical with these) *)
  color "wavelengths 0.70, 0.52, 0.48 by default" (0.1 +. (0.6 *. k 0.5 0.25 0.70), 0.1 +. (0.6 *. k 0.5 0.25 0.52),
                                        0.1 +. (0.6 *. k 0.5 0.25 0.48))
    (pixel (lit ^ film 0.5 0.25));
  color "irid_wavelength" (0.1 +. (0.6 *. k 0.3 0.4 0.5), 0.1 +. (0.6 *. k 0.3 0.4 0.2), 0.1 +. (0.6 *. k 0.3 0.4 0.1))
    (pixel ("global_settings { irid_wavelength rgb <0.5, 0.2, 0.1> }\n" ^ lit ^ film 0.3 0.4))

(* POV-Ray's object flags: no_image hides from camera rays but keeps the
   shadow, no_reflection hides from mirrors, double_illuminate lights the
   back by |cos| *)
let object_flags () =
  let floor = light30 ^ plane "" in
  let on_shadow_ray flag = Printf.sprintf "sphere { <0.2887, 0, 0.5>, 0.1 pigment { rgb 1 } %s }\n" flag in
  gray "default finish, nothing in the way" 0.61962 (pixel floor);
  gray "in the light's way: shadowed" 0.1 (pixel (floor ^ on_shadow_ray ""));
  gray "no_image still casts its shadow" 0.1 (pixel (floor ^ on_shadow_ray "no_image"));
  let in_view flag = Printf.sprintf "sphere { <0, 0, 0.5>, 0.1 pigment { rgb <1, 0, 0> } %s }\n" flag in
  color ~eps:1e-4 "seen: lit red" (0.6099, 0., 0.) (pixel (floor ^ in_view ""));
  gray "no_image: the plane behind it" 0.61962 (pixel (floor ^ in_view "no_image"));
  let mirror = "plane { z, 1 finish { ambient 0 diffuse 0 reflection 1 } }\n" in
  let behind flag =
    Printf.sprintf "sphere { <0, 0, -1>, 0.5 pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } %s }\n" flag
  in
  color "in the mirror" (0., 1., 0.) (pixel (mirror ^ behind ""));
  gray "no_reflection: not in the mirror" 0. (pixel (mirror ^ behind "no_reflection"));
  color "no_image: still in the mirror" (0., 1., 0.) (pixel (mirror ^ behind "no_image"));
  let back_lit flag = "light_source { <0, 0, 10>, rgb 1 }\n" ^ Printf.sprintf "plane { z, 1 pigment { rgb 1 } %s }\n" flag in
  gray "lit from behind: ambient only" 0.1 (pixel (back_lit ""));
  gray "double_illuminate: as from the front" 0.7 (pixel (back_lit "double_illuminate"));
  gray "double_illuminate off" 0.1 (pixel (back_lit "double_illuminate off"))

(* Media against closed forms and POV-Ray 3.7's numbers: a box from z = 1
   to z = 1 + d on the camera's axis, seen through its clear surface *)
let media () =
  let box ?(d = 2.) ?(extra = "") ?(bg = 0.) m =
    pixel
      (Printf.sprintf
         "background { rgb %g }\n%sbox { <-1,-1,1>, <1,1,%g> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow interior { %s } }\n"
         bg extra (1. +. d) m)
  in
  let left od n = (* POV-Ray's method 3 for a constant medium: a left sum over n stretches *)
    let s = ref 0. in
    for i = 0 to n - 1 do s := !s +. Float.exp (-.od *. float_of_int i /. float_of_int n) done;
    !s /. float_of_int n
  in
  gray "absorbing slab: exp(-a d)" (Float.exp (-1.)) (box ~bg:1. "media { absorption 0.5 }");
  color "absorption per channel" (Float.exp (-0.2), Float.exp (-1.), Float.exp (-2.))
    (box ~bg:1. "media { absorption <0.1, 0.5, 1> }");
  gray "emission alone: e d" 0.2 (box "media { emission 0.1 }");
  gray "emission and absorption: POV-Ray's left sum over 6 stretches" (0.2 *. left 2. 6)
    (box "media { emission 0.1 absorption 1 }");
  gray "the same, POV-Ray 3.7's picture" ~eps:2e-5 0.10167 (box "media { emission 0.1 absorption 1 }");
  gray "samples 4: 3 stretches" (0.2 *. left 2. 3) (box "media { emission 0.1 absorption 1 samples 4,4 }");
  gray "method 2: the midpoint" (0.2 *. Float.exp (-1.)) (box "media { emission 0.1 absorption 1 method 2 samples 1 }");
  (* method 2 in three intervals of a graded medium: each interval's
     midpoints dimmed by their own extinction over their distance into it,
     the interval by the depth before it (POV-Ray 3.7's 16-bit linear
     values; dimming each midpoint by the depth of the midpoints before
     it instead gave 40.7 dB against POV-Ray's picture) *)
  color ~eps:2e-5 "method 2, intervals 3, gradient density (POV-Ray 0.393561 0.543679 0.527428)"
    (0.393561, 0.543679, 0.527428)
    (pixel
       "camera { location <0, 0, -1> look_at 0 angle 10 }\n\
        box { <-3, -3, 0>, <3, 3, 8> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow\n\
        interior { media { emission <0.1, 0.07, 0.03> absorption <0.3, 0.15, 0.05> method 2 intervals 3 samples 2\n\
        density { gradient z color_map { [0 rgb 0.2] [1 rgb 1.5] } scale 8 } } } }\n\
        plane { -z, -9 pigment { rgb <0.9, 0.7, 0.5> } finish { ambient 1 diffuse 0 } }\n");
  gray "two media add" 0.3 (box "media { emission 0.1 } media { emission 0.05 }");
  gray "two densities multiply" 0.02 (box "media { emission 0.1 density { rgb 0.5 } density { rgb 0.2 } }");
  (* gradient z density over [0, 1): method 3 reads 6 stretches of 1/7,
     3 samples each: the mean of z is 3/7 (POV-Ray: 0.42771 at d = 0.999) *)
  gray ~eps:2e-5 "gradient density" 0.42771
    (box ~d:0.999 "media { emission 1 density { gradient z translate z } }");
  (* isotropic scattering of a light far on the side: phase 1; the light
     crosses 1 unit of the medium to the axis, the ray 1 unit: POV-Ray
     0.08682 *)
  let side = "light_source { <1000, 0, 1.5>, rgb 1 }\n" in
  gray ~eps:2e-5 "isotropic scattering" 0.08682 (box ~d:1. ~extra:side "media { scattering { 1, 0.1 } }");
  gray ~eps:1e-4 "numerical integral, no extinction: s d" 0.1
    (box ~d:1. ~extra:side "media { scattering { 1, 0.1 extinction 0 } }");
  gray ~eps:1e-4 "Henyey-Greenstein at 90 degrees" (0.1 *. 0.75 /. (1.25 ** 1.5))
    (box ~d:1. ~extra:side "media { scattering { 5, 0.1 eccentricity 0.5 extinction 0 } }");
  gray "media_interaction off" 0.
    (box ~d:1. ~extra:"light_source { <1000, 0, 1.5>, rgb 1 media_interaction off }\n" "media { scattering { 1, 0.1 } }");
  (* a shadowless light is POV-Ray's fill light, not in its media's list
     of lights: nothing scattered, and the ray unlit (a constant medium
     sampled as one stretch, as with no light); a spotlight written after
     shadowless is a spotlight again, its cone over the whole ray *)
  gray "shadowless: not scattered" 0.
    (box ~d:1. ~extra:"light_source { <1000, 0, 1.5>, rgb 1 shadowless }\n" "media { scattering { 1, 0.1 } }");
  (* three intervals: one stretch when unlit (a constant medium), three
     when a light crosses the ray; POV-Ray 3.7's pictures: with the
     shadowless light as with none, with a point light not *)
  let glow = "media { emission 0.1 absorption 1 intervals 3 }" in
  let unlit = box glow and lit = box ~extra:"light_source { <1000, 0, 1.5>, rgb 1 }\n" glow in
  if Float.abs (lit.r -. unlit.r) < 1e-4 then Alcotest.failf "a lit ray sampled as an unlit one (%g)" lit.r;
  color ~eps:0. "shadowless: sampled as unlit" (unlit.r, unlit.g, unlit.b)
    (box ~extra:"light_source { <1000, 0, 1.5>, rgb 1 shadowless }\n" glow);
  gray ~eps:2e-5 "shadowless, then spotlight: scattered" 0.08682
    (box ~d:1.
       ~extra:"light_source { <1000, 0, 1.5>, rgb 1 shadowless spotlight point_at <0, 0, 1.5> radius 10 falloff 10 }\n"
       "media { scattering { 1, 0.1 } }");
  (* a lit plane behind an absorbing box: the shadow ray is dimmed too *)
  gray ~eps:1e-4 "shadow through media" (Float.exp (-2.))
    (pixel
       "light_source { <0,0,-1000>, rgb 1 }\nplane { -z, -4 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\nbox { <-2,-2,1>, <2,2,3> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow interior { media { absorption 0.5 } } }\n");
  (* a hollow shell (a difference of spheres of radius 20 and 10) around
     the lit point: the shadow ray crosses its media over 10 units only,
     not over each sphere's own inside (POV-Ray 3.7: 0.606531) *)
  gray ~eps:2e-5 "shadow through a CSG shell's media" (Float.exp (-0.5))
    (pixel
       "light_source { <0,0,-100>, rgb 1 }\nplane { -z, -3 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
        difference { sphere { 0, 20 } sphere { 0, 10 } pigment { rgbf 1 } finish { ambient 0 diffuse 0 } hollow interior { media { absorption 0.05 } } }\n")

(* Scene-level (atmospheric) media: the camera at the origin looks along
   +z at a plane z = 3 whose inside is beyond it (the camera inside a
   plane is inside a solid: no atmosphere there) *)
(* A shadow ray meets a solid's interior_texture where it leaves the
   solid through its surface, its texture where it enters (POV-Ray's
   ComputeShadowColour). Ground lit from above through a clear sphere
   whose inside is opaque: shadowed (ambient 0.1 only); inside a filter
   green: green (0.1 + 0.9 f); a disc inside such a sphere is lit through
   the inside's filter alone. Values measured with povray 3.7. *)
let interior_texture_shadows () =
  let ground inside =
    pixel
      ("camera { location <0,5,-0.001> look_at <0,0,0> angle 5 }\nlight_source { <0,20,0>, rgb 1 }\n\
        plane { y, 0 pigment { rgb 1 } finish { ambient 0.1 diffuse 0.9 } }\n\
        sphere { <0,2,0>, 1 texture { pigment { rgbt 1 } } interior_texture { pigment { " ^ inside ^ " } } no_image }")
  in
  gray ~eps:2e-5 "opaque inside" 0.1 (ground "rgb <0.2,0.4,1>");
  color ~eps:2e-5 "filtering inside" (0.28, 1., 0.55) (ground "rgbf <0.2,1,0.5,1>");
  color ~eps:2e-5 "lit from inside" (0.28, 1., 0.55)
    (pixel
       "camera { location <0,-5,0.001> look_at <0,0,0> angle 5 }\nlight_source { <0,20,0>, rgb 1 }\n\
        disc { <0,0,0>, <0,-1,0>, 0.5 pigment { rgb 1 } finish { ambient 0.1 diffuse 0.9 } double_illuminate }\n\
        sphere { <0,0.5,0>, 1 texture { pigment { rgbf <1,0.5,0.5,1> } } \
        interior_texture { pigment { rgbf <0.2,1,0.5,1> } } no_image }")

(* Interior fade, as POV-Ray 3.7 applies it: where a ray leaves the
   object it hits, by that object's fade over the way from the last
   surface (an outer solid's fade only over the stretch that ends at its
   own surface, not where the ray enters an inner solid); the same for
   shadow rays. Values measured with povray 3.7 (1x1, 16-bit PNG) *)
let fade_rules () =
  let back = "background { rgb <.2,.4,.6> }\nplane { -z, -5 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n" in
  color ~eps:2e-5 "nested, seen" (0.03922, 0.17647, 0.01961)
    (pixel
       (back
       ^ "box { <-1,-1,1>, <1,1,4> pigment { rgbf 1 } finish { ambient 0 diffuse 0 } \
          interior { fade_distance 0.5 fade_power 1 fade_color <0.5,0,0> } }\n\
          box { <-0.5,-0.5,2>, <0.5,0.5,3> pigment { rgbf 1 } finish { ambient 0 diffuse 0 } \
          interior { fade_distance 0.25 fade_power 2 fade_color <0,0.5,0> } }"));
  let lit = "camera { location <0,0,-1> look_at <0,0,0> angle 10 }\nlight_source { <0, 0, -10>, rgb 1 }\n" in
  color ~eps:2e-5 "nested, in a shadow ray and seen" (0.01875, 0.045, 0.005)
    (pixel
       (lit
       ^ "plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
          box { <-5,-5,1>, <5,5,6> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } \
          interior { fade_distance 1 fade_power 1 fade_color <0.5,0,0> } }\n\
          box { <-4,-4,2>, <4,4,3> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } \
          interior { fade_distance 0.5 fade_power 2 fade_color <0,0.5,0> } }"));
  (* a merge of two fading spheres, each with its own interior: the
     shadow ray enters the second through its surface and leaves the
     first through its (the walls between are gone), and is faded by
     neither (POV-Ray's rule; the geometry alone would fade it) *)
  let csg kind =
    pixel
      (lit
      ^ "plane { -z, -6 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
      ^ kind
      ^ " { sphere { <-0.3,0,3>, 1 pigment { rgbf <1,1,1,0.95> } finish { ambient 0 diffuse 0 } \
         interior { ior 1 fade_distance 1 fade_power 1 fade_color <1,0,0> } }\n\
         sphere { <0.3,0,3.5>, 1 pigment { rgbf <1,1,1,0.95> } finish { ambient 0 diffuse 0 } \
         interior { ior 1 fade_distance 1 fade_power 1 fade_color <1,0,0> } } no_image }")
  in
  gray ~eps:2e-5 "merged spheres' shadow" 0.90249 (csg "merge");
  color ~eps:2e-5 "united spheres' shadow" (0.81451, 0.22551, 0.22551) (csg "union");
  (* an open hemisphere (clipped_by): the ray leaves it through the hole,
     unfaded, seen and as a shadow ray *)
  let bowl = "sphere { <0,0,3>, 2 clipped_by { plane { z, 3 } } pigment { rgbf 1 } finish { ambient 0 diffuse 0 } \
              interior { fade_distance 0.5 fade_power 1 fade_color <0.2,0,0> } }\n" in
  gray "clipped, seen" 1.
    (pixel ("background { rgb <.2,.4,.6> }\nbox { <-0.5,-0.5,4>, <0.5,0.5,4.5> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n" ^ bowl));
  color ~eps:2e-5 "clipped, lit through it" (0.31429, 0.14285, 0.14285)
    (pixel (lit ^ "disc { <0,0,4>, <0,0,-1>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" ^ bowl))

(* Several media along a ray, as POV-Ray 3.7 mixes them (media.cpp):
   their scattering summed and weighed by the mean of all their phases
   (a medium that does not scatter counts as isotropic), not each by its
   own; sampled by the settings of the first medium with the most
   intervals, the interiors in the order the ray entered them, with the
   smallest aa_threshold. Values measured with povray 3.7 (1x1, 16-bit
   PNG); a box 2 deep at z = 1 to 3, a light up and to the right *)
let mixed_media () =
  let box media =
    pixel
      ("light_source { <10, 20, -5>, rgb 2 }\n\
        box { <-1,-1,1>, <1,1,3> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n\
        interior { media { method 3 samples 4 intervals 1 scattering { 2, rgb 0.3 extinction 1 } }\n"
      ^ media ^ " } }\n")
  in
  color ~eps:2e-5 "Mie hazy and Rayleigh in one interior" (0.62361, 0.68786, 0.70678)
    (box "media { method 3 samples 2 intervals 1 scattering { 4, rgb <0.25,0.6,0.9>*0.5 extinction 1 } }");
  color ~eps:2e-5 "Mie hazy and an absorbing medium (isotropic in the mean)" (0.43249, 0.33013, 0.25849)
    (box "media { absorption <0.2, 0.4, 0.6> }");
  (* two interiors, the Rayleigh box entered second and sampled by the
     Mie box's settings; the shadow rays start in the camera ray's
     interiors and leave each where they cross it, no interior media on
     their last stretch to the light (5% off before these rules) *)
  color ~eps:2e-5 "overlapping interiors" (0.59461, 0.71795, 0.77375)
    (pixel
       "light_source { <10, 20, -5>, rgb 2 }\n\
        box { <-1,-1,1>, <1,1,3> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n\
        interior { media { method 3 samples 4 intervals 1 scattering { 2, rgb 0.3 extinction 1 } } } }\n\
        box { <-0.5,-0.5,2>, <0.5,0.5,4> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n\
        interior { media { method 3 samples 2 intervals 1 scattering { 4, rgb <0.25,0.6,0.9>*0.5 extinction 1 } } } }\n");
  (* a scattering box inside a larger hollow box with no media, lit
     along the view: POV-Ray's shadow rays from samples on the inner
     box's face start in both, cross no inner surface, and are dimmed by
     its media up to the outer box's face: darker than the box alone *)
  let inner outer =
    pixel
      ("light_source { <0,0,-30>, rgb 0.5 }\n" ^ outer
     ^ "box { <-0.5,-0.5,1.5>, <0.5,0.5,2.5> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n\
        interior { media { method 3 samples 2 intervals 1 scattering { 1, rgb 0.3 extinction 1 } } } }\n")
  in
  gray ~eps:2e-5 "a medium alone" 0.12702 (inner "");
  gray ~eps:2e-5 "inside a hollow box without media" 0.12352
    (inner "box { <-1,-1,1>, <1,1,3> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }\n")

let atmosphere () =
  let glow = "plane { -z, -3 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } }\n" in
  let dark = "plane { -z, -3 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n" in
  gray "absorbing atmosphere: exp(-a d)" (Float.exp (-0.6)) (pixel (glow ^ "media { absorption 0.2 }"));
  gray "emitting atmosphere: e d" 0.3 (pixel (dark ^ "media { emission 0.1 }"));
  gray "the camera inside a solid plane sees none" 1.
    (pixel "plane { z, 3 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } }\nmedia { absorption 0.2 }");
  (* POV-Ray 3.7: 0.135332 (exp(-2)) with absorption 1e-10 and nothing hit *)
  gray ~eps:1e-5 "a ray that hits nothing crosses 2e10 units" (Float.exp (-2.))
    (pixel "background { rgb 1 }\nmedia { absorption 1e-10 }");
  (* a clear box around the camera, to z = 2 *)
  let around h = Printf.sprintf "box { -2, 2 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } %s }\n" h in
  gray "not inside a solid" (Float.exp (-0.2)) (pixel (glow ^ around "" ^ "media { absorption 0.2 }"));
  gray "inside a hollow object" (Float.exp (-0.6)) (pixel (glow ^ around "hollow" ^ "media { absorption 0.2 }"));
  (* a hollow object's media first, the atmosphere over them (POV-Ray
     3.7's picture: 0.9801 for the same at 10 units) *)
  gray "hollow media under the atmosphere"
    (* beyond the box: 1 + 0.1 emitted over [2, 3]; the box's media over
       [0, 2] dim it; the atmosphere adds its 0.2 undimmed by them *)
    ((1.1 *. Float.exp (-0.1)) +. 0.2)
    (pixel
       (glow ^ around "hollow interior { media { absorption 0.05 } }" ^ "media { emission 0.1 }"));
  (* shadow rays: POV-Ray dims them only for media_attenuation lights,
     over their whole length (3 to -7: 10 units), solids crossed or not *)
  let lit att extra =
    pixel
      (Printf.sprintf
         "light_source { <0,0,-7>, rgb 1 %s }\nplane { -z, -3 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n%smedia { absorption 0.05 }"
         att extra)
  in
  gray ~eps:2e-5 "media_attenuation off (POV-Ray 0.860716)" (Float.exp (-0.15)) (lit "" "");
  gray ~eps:2e-5 "media_attenuation on (POV-Ray 0.522042)" (Float.exp (-0.65)) (lit "media_attenuation on" "");
  gray ~eps:2e-5 "media_attenuation through a clear solid" (Float.exp (-0.65))
    (lit "media_attenuation on" "box { <-1,-1,-5>, <1,1,-4> pigment { rgbf 1 } }\n");
  (* fog on shadow rays: only for lights with media_attenuation and
     media_interaction on, and only where the ray runs outside solids;
     fog of distance 20 over the 3 units to the plane and the 10 back to
     the light (POV-Ray 3.7's values at 16 bits, linear) *)
  let fogged att extra fog =
    pixel
      (Printf.sprintf
         "light_source { <0,0,-7>, rgb 1 %s }\nplane { -z, -3 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n%sfog { %s }"
         att extra fog)
  in
  let black = "color rgb 0 distance 20" in
  gray ~eps:2e-5 "fog, media_attenuation off (POV-Ray 0.860716)" (Float.exp (-0.15)) (fogged "" "" black);
  gray ~eps:2e-5 "fog, media_attenuation on (POV-Ray 0.522042)" (Float.exp (-0.65))
    (fogged "media_attenuation on" "" black);
  gray ~eps:2e-5 "fog, media_interaction off (POV-Ray 0.860716)" (Float.exp (-0.15))
    (fogged "media_attenuation on media_interaction off" "" black);
  gray ~eps:2e-5 "fog skips the 1 unit inside a clear solid (POV-Ray 0.548806)" (Float.exp (-0.6))
    (fogged "media_attenuation on" "box { <-1,-1,-5>, <1,1,-4> pigment { rgbf 1 } }\n" black);
  gray ~eps:2e-5 "fog through a clear hollow box (POV-Ray 0.522042)" (Float.exp (-0.65))
    (fogged "media_attenuation on" "box { <-1,-1,-5>, <1,1,-4> pigment { rgbf 1 } hollow }\n" black);
  (* a ground fog: density 1 / (1 + h^2) above 0 along z, whose mean over
     [a, b] is (atan b - atan a) / (b - a): the camera ray from 0 to 3,
     the shadow ray from 3 down to -7 (density 1 below 0) *)
  let ground a b = if a <= 0. && b <= 0. then 1. else if a <= 0. then (Float.atan b -. a) /. (b -. a) else (Float.atan b -. Float.atan a) /. (b -. a) in
  gray ~eps:2e-5 "ground fog on a shadow ray (POV-Ray 0.621942)"
    (Float.exp (-.((3. *. ground 0. 3.) +. (10. *. ground (-7.) 3.)) /. 20.))
    (fogged "media_attenuation on" "" "fog_type 2 fog_alt 1 fog_offset 0 up z color rgb 0 distance 20");
  (* a filtering, transmitting fog: the light is tinted by (1 - f + f c)
     and dimmed by at least the transmit t on each ray; the camera ray
     adds (1 - a) c *)
  (let f = 0.5 and t = 0.1 in
   let a d = Float.max t (Float.exp (-.d /. 20.)) in
   let seen c = ((1. -. a 3.) *. c) +. (a 3. *. (1. -. f +. (f *. c)) *. a 10. *. (1. -. f +. (f *. c))) in
   color ~eps:2e-5 "fog filter and transmit on a shadow ray (POV-Ray 0.363302 0.215793 0.130510)"
     (seen 0.5, seen 0.2, seen 0.)
     (fogged "media_attenuation on" "" "color rgbft <0.5, 0.2, 0, 0.5, 0.1> distance 20"));
  (* single scattering of a light: none when it has media_interaction off *)
  gray "media_interaction off" 0.
    (pixel ("light_source { <0, 5, 1>, rgb 1 media_interaction off }\n" ^ dark ^ "media { scattering { 1, 0.1 } }"));
  (* a thin spotlight beam across the ray, seen from the side: a cone of
     half-angle 1 degree, full strength inside (radius = falloff,
     tightness 0), its apex 5 units above the ray at z = 1.6: the ray runs
     inside it over |z - 1.6| <= 5 tan 1 deg. Each point there scatters
     sigma (isotropic, unshadowed, no media_attenuation) toward the eye,
     dimmed by exp (-sigma z) on the way: in all
     exp (-sigma z1) - exp (-sigma z2). POV-Ray samples that stretch on
     its own (10 samples would step over it otherwise: 3 units in 6
     stretches of 3/7, read every 3/14, none within the beam) *)
  let sigma = 0.1 and h = 5. *. Float.tan (Float.pi /. 180.) in
  let beam = Float.exp (-.sigma *. (1.6 -. h)) -. Float.exp (-.sigma *. (1.6 +. h)) in
  let spot x =
    Printf.sprintf
      "light_source { <0, 5, 1.6>, rgb 1 spotlight point_at <0, 0, 1.6> radius 1 falloff 1 tightness 0%s }\n%smedia { scattering { 1, %g } }\n"
      x dark sigma
  in
  let seen = pixel (spot "") in
  gray ~eps:(5e-3 *. beam) "a thin spotlight beam through scattering media" beam seen;
  (* and exactly as POV-Ray sums it: the beam's stretch in 6 pieces of
     [w], each weighing its start (constant media), dimmed by the depth
     before it *)
  let z1 = 1.6 -. h and w = 2. *. h /. 6. in
  let sum = ref 0. in
  for k = 0 to 5 do
    sum := !sum +. (sigma *. w *. Float.exp (-.sigma *. (z1 +. (float_of_int k *. w))))
  done;
  gray ~eps:1e-7 "the beam summed as POV-Ray sums it" !sum seen;
  gray "a beam with media_interaction off" 0. (pixel (spot " media_interaction off"));
  let lit_air = pixel ("light_source { <0, 5, 1>, rgb 1 }\n" ^ dark ^ "media { scattering { 1, 0.1 } }") in
  if not (lit_air.r > 0.01) then Alcotest.failf "scattered light expected, got %g" lit_air.r

(* #declare'd media and densities, used and edited *)
let declared_media () =
  let box ?(d = 2.) decl m =
    pixel
      (Printf.sprintf
         "%s\nbox { <-1,-1,1>, <1,1,%g> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow interior { %s } }\n"
         decl (1. +. d) m)
  in
  gray "a declared media" 0.2 (box "#declare M = media { emission 0.1 }" "media { M }");
  gray "a declared media edited" 0.3 (box "#declare M = media { emission 0.1 }" "media { M emission 0.15 }");
  gray "a declared media twice" 0.4 (box "#declare M = media { emission 0.1 }" "media { M } media { M }");
  gray "a declared density" 0.1 (box "#declare D = density { rgb 0.5 }" "media { emission 0.1 density { D } }");
  gray "a declared density edited" ~eps:2e-5 (2. *. 0.42771)
    (box ~d:0.999 "#declare D = density { gradient z }" "media { emission 2 density { D translate z } }");
  gray "a density_map" ~eps:2e-5 (2. *. 0.42771)
    (box ~d:0.999 "#declare D = density { rgb 2 }"
       "media { emission 1 density { gradient z translate z density_map { [0 rgb 0] [1 D] } } }");
  gray "declared atmosphere" 0.3
    (pixel "#declare M = media { emission 0.1 }\nplane { -z, -3 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\nmedia { M }")

(* light_group, against POV-Ray 3.7 (probe scenes rendered with +FN16
   File_Gamma=1.0, pixels read back). An orthographic view 8 x 6 units
   wide at 64 x 48: pixel (16, 24) is at x = -1.9375, y = -0.0625, on a
   sphere of radius 0.8 centred at x = -2, where the normal's z is
   0.99389: a light straight from the eye gives 0.6 x 0.99389 = 0.59633
   of its colour (POV-Ray: 0.5964; the lights 1000 units away are a few
   1e-4 off straight for the other spheres). *)
let light_group () =
  let view =
    "global_settings { ambient_light 0 }\n\
     camera { orthographic location <0,0,-10> look_at 0 right 8*x up 6*y }\n\
     #default { finish { ambient 0 diffuse 0.6 } }\n"
  in
  let at src x y = pixel ~w:64 ~h:48 ~x ~y (view ^ src) in
  let ball c = Printf.sprintf "sphere { %s, 0.8 pigment { rgb 1 } }" c in
  let eye c = Printf.sprintf "light_source { <0,0,-1000> rgb %s }" c in
  let full = 0.6 *. 0.99389 in
  let groups =
    String.concat "\n"
      [ eye "<0,0,0.5>";
        "light_group { " ^ eye "<1,0,0>" ^ ball "<-2,0,0>" ^ " }";
        "light_group { " ^ eye "<0,1,0>" ^ ball "<0,0,0>" ^ " global_lights on }";
        ball "<2,0,0>";
        (* nested: an inner group's surfaces see its own lights only, and
           the outermost group's global_lights decides for them *)
        "light_group { " ^ eye "<0,0.25,0>" ^ " light_group { " ^ eye "<0.25,0,0>" ^ ball "<-2,2,0>"
        ^ " global_lights on } " ^ ball "<0,2,0>" ^ " }";
        "light_group { " ^ eye "<0,0.25,0>" ^ " light_group { " ^ eye "<0.25,0,0>" ^ ball "<-2,-2,0>"
        ^ " } " ^ ball "<0,-2,0>" ^ " global_lights on }";
        (* no lights: only the global ones, with global_lights on *)
        "light_group { " ^ ball "<2,2,0>" ^ " }";
        "light_group { " ^ ball "<2,-2,0>" ^ " global_lights on }" ]
  in
  color ~eps:5e-4 "in a group: its own light only" (full, 0., 0.) (at groups 16 24);
  color ~eps:5e-4 "global_lights on: both" (0., full, full /. 2.) (at groups 32 24);
  color ~eps:5e-4 "outside: the global light only" (0., 0., full /. 2.) (at groups 48 24);
  color ~eps:5e-4 "inner group, outer off: inner lights, no global" (full /. 4., 0., 0.) (at groups 16 8);
  color ~eps:5e-4 "outer group's own surface" (0., full /. 4., 0.) (at groups 32 8);
  color ~eps:5e-4 "inner group, outer on: inner lights and global" (full /. 4., 0., full /. 2.) (at groups 16 40);
  color ~eps:5e-4 "outer on, its own surface" (0., full /. 4., full /. 2.) (at groups 32 40);
  color "a group without lights is dark" (0., 0., 0.) (at groups 48 8);
  color ~eps:5e-4 "a group without lights, global_lights on" (0., 0., full /. 2.) (at groups 48 40);
  (* the group's lights move with it: a light 3 units in front of the
     sphere, the sphere moved 2 units left (POV-Ray: 0.5932) *)
  let moved =
    let px = 0.0625 and py = -0.0625 in
    let pz = -.Float.sqrt ((0.8 *. 0.8) -. (px *. px) -. (py *. py)) in
    let lx = -.px and ly = -.py and lz = -3. -. pz in
    0.6 *. ((px *. lx) +. (py *. ly) +. (pz *. lz)) /. 0.8 /. Float.sqrt ((lx *. lx) +. (ly *. ly) +. (lz *. lz))
  in
  color ~eps:5e-4 "a declared group, moved: its light moves too" (moved, 0., 0.)
    (at ("#declare G = light_group { light_source { <0,0,-3> rgb <1,0,0> } " ^ ball "0" ^ " }\n\
          object { G translate <-2,0,0> }") 16 24);
  (* shadows are not grouped: an object outside a group shadows it from
     the group's light, and a group's object shadows the rest from the
     global lights (POV-Ray: 0.3278 lit, 0 behind the slabs) *)
  let shadow slab =
    "light_group { light_source { <-2,1000,0> rgb 1 } " ^ ball "<-2,-2,0>" ^ " }\n"
    ^ (if slab then "box { <-2.5,-0.8,-1>, <-1.5,-0.7,1> pigment { rgb 1 } }\n" else "")
    ^ "light_source { <2,1000,0> rgb 1 }\n" ^ ball "<2,-2,0>" ^ "\n"
    ^ if slab then "light_group { light_source { <0,0,-1000> rgb 0 } box { <1.5,-0.8,-1>, <2.5,-0.7,1> } }\n" else ""
  in
  gray ~eps:5e-4 "lit by the group's light" 0.3278 (at (shadow false) 16 36);
  gray ~eps:5e-4 "lit by the global light" 0.3278 (at (shadow false) 48 36);
  gray "an outside object shadows a group's light" 0. (at (shadow true) 16 36);
  gray "a group's object shadows a global light" 0. (at (shadow true) 48 36)

(* A negative transmit (POV-Ray's transmitfx.pov): the surface lets the
   picture behind through with its sign turned, (1 - t) c + t behind;
   POV-Ray traces on while the transmitted colour is large in absolute
   value. rgb 0.5 transmit -1 with ambient 1 over a wall of ambient 1:
   2 x 0.5 - wall. *)
let negative_transmit () =
  let c =
    Scn.pixel
      "plane { z, 1 pigment { rgb 0.5 transmit -1 } finish { ambient 1 diffuse 0 } }\n\
       plane { z, 2 pigment { rgb <0.2, 0.4, 0.6> } finish { ambient 1 diffuse 0 } }"
  in
  Scn.color "1 - the wall" (0.8, 0.6, 0.4) c

(* sky_sphere layers, by POV-Ray's rule of the scene's version: 3.7 weighs
   a layer by the colour the layers above let through (the top's rgb x
   filter), 3.6 by their filter and transmit as one number; a top layer
   rgbf <0.5, 0.5, 0.5, 0.8> over rgb <0.2, 0.4, 0.6>, background black *)
let sky_layers () =
  let sky v =
    Scn.pixel ~raw:true
      (Printf.sprintf
         "#version %s;\nglobal_settings { assumed_gamma 1.0 }\n\
          sky_sphere { pigment { rgb <0.2, 0.4, 0.6> } pigment { rgbf <0.5, 0.5, 0.5, 0.8> } }"
         v)
  in
  Scn.color "3.7: 0.1 + 0.4 x the layer below" (0.18, 0.26, 0.34) (sky "3.7");
  Scn.color "3.6: 0.1 + 0.8 x the layer below" (0.26, 0.42, 0.58) (sky "3.6")

(* Media only along a hollow ray (POV-Ray 3.7, measured): an emitting
   sphere that is not hollow shows nothing; a clear solid sphere inside a
   hollow emitting one leaves its media to the shell (1 unit before and 1
   after the solid: half of the 4 units straight through) *)
let media_hollow_rays () =
  let scene inner hollow =
    Scn.pixel
      (Printf.sprintf
         "sphere { <0,0,5>, 2 pigment { rgbf 1 } %s interior { media { emission 0.1 } } }\n%s"
         (if hollow then "hollow" else "")
         (if inner then "sphere { <0,0,5>, 1 pigment { rgbf 1 } }" else ""))
  in
  let g (c : Color.t) = c.g in
  let through = g (scene false true) in
  if not (through > 0.3) then Alcotest.failf "4 units of emission 0.1: %g" through;
  Scn.close "not hollow: no media" 0. (g (scene false false));
  Scn.close ~eps:1e-9 "a solid inside: the shell's half" (through /. 2.) (g (scene true true))

let tests =
  ( "whitted",
    [
      Alcotest.test_case "finishes" `Quick finishes;
      Alcotest.test_case "media only along hollow rays (POV-Ray 3.7)" `Quick media_hollow_rays;
      Alcotest.test_case "sky_sphere layers: POV-Ray 3.7's rule and 3.6's" `Quick sky_layers;
      Alcotest.test_case "negative transmit: the picture behind, its sign turned" `Quick negative_transmit;
      Alcotest.test_case "lights" `Quick lights;
      Alcotest.test_case "shadows" `Quick shadows;
      Alcotest.test_case "light_group" `Quick light_group;
      Alcotest.test_case "reflection" `Quick reflection;
      Alcotest.test_case "transparency" `Quick transparency;
      Alcotest.test_case "conserve_energy and layers' reflections (POV-Ray's values)" `Quick conserve_energy;
      Alcotest.test_case "no_image, no_reflection, double_illuminate" `Quick object_flags;
      Alcotest.test_case "average pigment_map" `Quick average;
      Alcotest.test_case "faked caustics" `Quick caustics;
      Alcotest.test_case "iridescence" `Quick irid;
      Alcotest.test_case "media" `Quick media;
      Alcotest.test_case "atmospheric media" `Quick atmosphere;
      Alcotest.test_case "several media: POV-Ray's mixing and sampling rules" `Quick mixed_media;
      Alcotest.test_case "interior fade in nested and clipped solids (POV-Ray's values)" `Quick fade_rules;
      Alcotest.test_case "shadow rays meet the interior_texture where they leave a solid" `Quick interior_texture_shadows;
      Alcotest.test_case "declared media and densities" `Quick declared_media;
      Alcotest.test_case "pigment and finish edit what they are written over" `Quick edits;
      Alcotest.test_case "pigment functions inside nested maps" `Quick nested_pigment_function;
      Alcotest.test_case "focal blur" `Quick focal_blur;
      Alcotest.test_case "#default texture" `Quick default_texture;
      Alcotest.test_case "normal slope as POV-Ray" `Quick normal_slope;
      Alcotest.test_case "ripples and waves normals: POV-Ray's formula" `Quick ripples_normal;
      Alcotest.test_case "normal_map and average as POV-Ray" `Quick normal_maps;
      Alcotest.test_case "average of textures as POV-Ray" `Quick average_textures;
      Alcotest.test_case "trace levels" `Quick levels;
      Alcotest.test_case "layers and sky" `Quick layers;
      Alcotest.test_case "declared maps, layered textures, materials" `Quick declared;
      Alcotest.test_case "the common case allocates nothing" `Quick allocation;
      Alcotest.test_case "patterns, normals and skies allocate nothing" `Quick allocation_textures;
      Alcotest.test_case "fog, media, rainbows and superellipsoids allocate nothing" `Quick allocation_media;
      Alcotest.test_case "text patterns, crackle, internal functions, height fields and nested glass allocate nothing" `Quick allocation_corners;
      Alcotest.test_case "64 overlapping glass interiors allocate nothing" `Quick allocation_many_glasses;
      Alcotest.test_case "faked caustics allocate nothing" `Quick allocation_caustics;
      Alcotest.test_case "spline functions of the four kinds and transform functions allocate nothing" `Quick
        allocation_spline_functions;
    ] )
