(* Fog and media in Monte Carlo mode, against closed forms: transmittance
   and emission of homogeneous and graded slabs, white furnaces of
   scattering media (energy conserved by every phase function), fog's
   blend on an emitting wall, the phase functions' sampling (chi-square),
   agreement with whitted mode where both models are exact (absorption and
   emission; single scattering a quarter of whitted's), light sampling
   and phase sampling alike, media inside glass as the equivalent
   exponential fade, and no allocation. *)
open Camlray

let render = Test_path.render
let mean = Test_path.mean
let header = Test_path.header

(* the mean of a channel over an image *)
let channel_mean img c =
  let s = ref 0. in
  for y = 0 to Image.height img - 1 do
    for x = 0 to Image.width img - 1 do
      let r, g, b = Helpers.pixel img x y in
      s := !s +. match c with 0 -> r | 1 -> g | _ -> b
    done
  done;
  !s /. float (Image.width img * Image.height img)

(* every pixel's channels equal to [e] (r, g, b) to [tol] relative *)
let every what img (er, eg, eb) tol =
  for y = 0 to Image.height img - 1 do
    for x = 0 to Image.width img - 1 do
      let r, g, b = Helpers.pixel img x y in
      List.iter
        (fun (v, e) ->
          if Float.abs (v -. e) > tol *. Float.max 1e-3 (Float.abs e) then
            Alcotest.failf "%s: pixel (%d,%d) is %.12g, expected %.12g" what x y v e)
        [ (r, er); (g, eg); (b, eb) ]
    done
  done

let means what img (er, eg, eb) tol =
  List.iteri
    (fun c e ->
      let v = channel_mean img c in
      if Float.abs (v -. e) > tol *. Float.max 1e-3 (Float.abs e) then
        Alcotest.failf "%s: channel %d mean %.6g, expected %.6g (+- %g relative)" what c v e tol)
    [ er; eg; eb ]

(* a clear hollow container: pigment rgbt 1, nothing of its own *)
let clear = "pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow"

(* An orthographic camera looking along +z through a slab z in [0, 1]
   (x and y far wider than the view) at the background or at an emitting
   wall *)
let slab ?(bg = "rgb 0") media =
  header
  ^ "camera { orthographic location <0,0,-3> look_at 0 right 2*x up 2*y }\n"
  ^ "background { " ^ bg ^ " }\n"
  ^ "box { <-50,-50,0>, <50,50,1> " ^ clear ^ " interior { media { " ^ media ^ " } } }\n"

let e3 f (a, b, c) = (f a, f b, f c)

let transmittance () =
  (* homogeneous: exp (-sigma d), exactly, every sample *)
  let img = render ~w:8 ~h:8 ~spp:4 ~depth:8 (slab ~bg:"rgb 1" "absorption <0.5, 1, 3>") in
  every "absorbing slab" img (e3 (fun s -> Float.exp (-.s)) (0.5, 1., 3.)) 1e-12;
  (* a density growing as z across it (gradient z): optical depth sigma /
     2, found by tracking (the camera rays) *)
  let img = render ~w:32 ~h:32 ~spp:16 ~depth:8 (slab ~bg:"rgb 1" "absorption <1, 2, 4> density { gradient z }") in
  means "graded absorbing slab" img (e3 (fun s -> Float.exp (-.s /. 2.)) (1., 2., 4.)) 0.03;
  (* and by ratio tracking (shadow rays): a wall at x = 0 facing -x, lit
     by a parallel light along +x through a slab x in [-2, -1] whose
     density grows from 1/8 to 3/8 across it, seen from between them; one
     bounce, nothing else lit: 0.8 exp (-sigma / 4) *)
  let text =
    header
    ^ "camera { orthographic location <-0.5,0,0> look_at <1,0,0> right 1*z up 1*y }\n\
       light_source { <-100,0,0> rgb 1 parallel point_at 0 }\n\
       plane { x, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }\n\
       box { <-2,-50,-50>, <-1,50,50> " ^ clear
    ^ " interior { media { absorption <1, 2, 4> density { gradient x scale 4 translate -2.5*x } } } }\n"
  in
  let img = render ~w:32 ~h:32 ~spp:16 ~depth:2 text in
  means "a wall lit through a graded slab" img (e3 (fun s -> 0.8 *. Float.exp (-.s /. 4.)) (1., 2., 4.)) 0.03

let emission () =
  (* homogeneous: e (1 - exp (-sigma d)) / sigma, exactly *)
  let e = (0.6, 0.3, 0.9) in
  let img = render ~w:8 ~h:8 ~spp:4 ~depth:8 (slab "emission <0.6, 0.3, 0.9> absorption 1.5") in
  every "emitting slab" img (e3 (fun e -> e *. (1. -. Float.exp (-1.5)) /. 1.5) e) 1e-12;
  every "emitting, not absorbing" (render ~w:4 ~h:4 ~spp:1 ~depth:8 (slab "emission <0.6, 0.3, 0.9>")) e 1e-12;
  (* density z: emission e z, dimmed by exp (-sigma z^2 / 2): (e / sigma)
     (1 - exp (-sigma / 2)); without absorption e / 2 *)
  let img =
    render ~w:32 ~h:32 ~spp:16 ~depth:8 (slab "emission <0.6, 0.3, 0.9> absorption 1.5 density { gradient z }")
  in
  means "graded emitting slab" img (e3 (fun e -> e /. 1.5 *. (1. -. Float.exp (-0.75))) e) 0.03;
  let img = render ~w:32 ~h:32 ~spp:16 ~depth:8 (slab "emission <0.6, 0.3, 0.9> density { gradient z }") in
  means "graded emitting slab, no absorption" img (e3 (fun e -> e /. 2.) e) 0.03

(* A medium of albedo 1 in a sphere under a sky of radiance 1: every
   pixel 1 (all bounces: depth 256) *)
let furnace media =
  header ^ "camera { location <0,0,-4> look_at 0 angle 50 }\nbackground { rgb 1 }\n"
  ^ "sphere { 0, 1 " ^ clear ^ " interior { media { " ^ media ^ " } } }\n"

let scattering_furnace () =
  List.iter
    (fun (what, media) ->
      let img = render ~w:12 ~h:12 ~spp:256 ~depth:256 (furnace media) in
      means what img (1., 1., 1.) 0.01;
      every what img (1., 1., 1.) 0.35)
    [
      ("isotropic", "scattering { 1, 2 }");
      ("Henyey-Greenstein 0.7", "scattering { 5, 2 eccentricity 0.7 }");
      ("Henyey-Greenstein -0.5", "scattering { 5, 1 eccentricity -0.5 }");
      ("Mie hazy", "scattering { 2, 1.5 }");
      ("Mie murky", "scattering { 3, 1.5 }");
      ("Rayleigh, coloured", "scattering { 4, <0.5, 1, 3> }");
      ("density (tracking)", "scattering { 1, 3 } density { spherical }");
    ];
  (* absorbing too: less comes out, never more *)
  let img = render ~w:12 ~h:12 ~spp:16 ~depth:64 (furnace "scattering { 1, 2 } absorption 0.5") in
  let m = mean img in
  if not (m < 0.97 && m > 0.3) then Alcotest.failf "albedo 0.8: mean %g" m

(* Light sampling at medium vertices (lights, an emissive sphere, the
   sky, MIS with the phase function) and phase sampling alone find the
   same light *)
let nee_vs_phase () =
  let text =
    header
    ^ "camera { location <0,0,-5> look_at 0 angle 45 }\n\
       sky_sphere { pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.6>] [1 rgb 1] } } }\n\
       sphere { 0, 1.2 " ^ clear
    ^ " interior { media { scattering { 5, <0.8, 0.6, 0.4> eccentricity 0.5 } absorption 0.2 } } }\n\
       sphere { 0, 0.5 " ^ clear
    ^ " interior { media { scattering { 1, 2 } density { spherical scale 0.5 } } } }\n\
       sphere { <1.5, 1.5, 0>, 0.4 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 4 } }\n"
  in
  let a = render ~w:16 ~h:16 ~spp:256 ~depth:16 text in
  let b = render ~nee:false ~seed:2 ~w:16 ~h:16 ~spp:1024 ~depth:16 text in
  for c = 0 to 2 do
    let ma = channel_mean a c and mb = channel_mean b c in
    if Float.abs (ma -. mb) > 0.02 *. ma then Alcotest.failf "channel %d: NEE+MIS %g vs phase sampling %g" c ma mb
  done

(* Fog on a wall of constant radiance L at distance d: T L + (1 - T) C,
   T = exp (-d / D); with filter f and transmit t, a = max(t, T):
   a (1 - f + f C) L + (1 - a) C. The same as whitted mode's. *)
let fog () =
  let wall fog =
    header
    ^ "camera { orthographic location <0,0,-1> look_at 0 right 2*x up 2*y }\n\
       plane { -z, -9 pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0 diffuse 0 emission 1 } }\n"
    ^ fog ^ "\n"
  in
  let l = (0.2, 0.5, 0.9) and c = (0.9, 0.6, 0.3) in
  let blend a f =
    let (lr, lg, lb), (cr, cg, cb) = (l, c) in
    let one l c = (a *. (1. -. f +. (f *. c)) *. l) +. ((1. -. a) *. c) in
    (one lr cr, one lg cg, one lb cb)
  in
  let t = Float.exp (-10. /. 8.) in
  let text = wall "fog { distance 8 color rgb <0.9, 0.6, 0.3> }" in
  every "constant fog" (render ~w:6 ~h:6 ~spp:4 ~depth:4 text) (blend t 0.) 1e-12;
  every "whitted's" (Helpers.render_whitted ~width:6 ~height:6 text) (blend t 0.) 1e-12;
  let text = wall "fog { distance 8 color rgbft <0.9, 0.6, 0.3, 0.5, 0.4> }" in
  every "filter and transmit" (render ~w:6 ~h:6 ~spp:4 ~depth:4 text) (blend (Float.max 0.4 t) 0.5) 1e-12;
  (* ground fog with turbulence, and a second fog: the altitudes vary
     across a pixel, so mc's pixel means against whitted's boxed pixels *)
  let text =
    wall
      "fog { fog_type 2 distance 3 fog_offset 0.1 fog_alt 0.4 turbulence 0.8 color rgb <0.7, 0.8, 0.9> }\n\
       fog { distance 30 color rgbf <0.9, 0.6, 0.3, 0.5> }"
  in
  let mc = render ~w:16 ~h:16 ~spp:16 ~depth:4 text and wh = Test_path.whitted_boxed ~w:16 ~h:16 ~k:4 text in
  let p = Test_path.psnr mc wh in
  if p < 50. then Alcotest.failf "ground fog: mc against whitted %.1f dB (at least 50)" p;
  (* the sky: all fog, the fog's colour *)
  let img =
    render ~w:4 ~h:4 ~spp:1 ~depth:4
      (header ^ "camera { location 0 look_at z }\nbackground { rgb 0.3 }\nfog { distance 100 color rgb <0.9, 0.6, 0.3> }\n")
  in
  every "the sky" img c 1e-12

(* Absorption and emission (no scattering): whitted mode's sampling is
   exact for constant media in separate solids, so the pictures agree
   but for the pixels' edges (mc spreads its samples over the pixel) *)
let vs_whitted () =
  let check what text =
    let w = 32 and h = 24 in
    let mc = render ~w ~h ~spp:64 ~depth:8 text and wh = Test_path.whitted_boxed ~w ~h ~k:4 text in
    let p = Test_path.psnr mc wh in
    if Sys.getenv_opt "MC_VERBOSE" <> None then Printf.printf "%s: %.1f dB\n" what p;
    if p < 40. then Alcotest.failf "%s: mc against whitted %.1f dB (at least 40)" what p
  in
  check "absorbing box over an emitting sphere"
    (header
    ^ "camera { location <0,0,-6> look_at 0 angle 40 }\nbackground { rgb <0.3, 0.5, 0.8> }\n\
       box { <-2,-1,-0.5>, <0.3,1,0.5> " ^ clear
    ^ " interior { media { absorption <0.6, 0.3, 0.1> } } }\n\
       sphere { <0.8,0,1.5>, 1.2 " ^ clear ^ " interior { media { emission <0.5, 0.3, 0.1> } } }\n");
  (* a plane lit through a box whose absorption varies linearly across
     it (whitted's quadrature exact there), its coloured shadow *)
  check "a coloured shadow through absorbing media"
    (header
    ^ "camera { location <0,4,-6> look_at 0 angle 50 }\nlight_source { <0, 10, 0> rgb 1 }\n\
       plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }\n\
       box { <-1,1,-1>, <1,2,1> " ^ clear
    ^ " interior { media { absorption <0.2, 1, 2> density { gradient x scale 4 translate -2*x } } } }\n")

(* Single scattering of a parallel light in a slab of isotropic medium
   (depth 2: the camera ray crosses the clear wall, scatters once):
   whitted mode's (POV-Ray's) scattering x phase x c, mc mode's a quarter
   of it (its light of colour c has intensity pi c, the phase function
   1 / (4 pi)). Method 2 with many samples: whitted's quadrature exact to
   1e-4. *)
let single_scattering () =
  let text =
    header
    ^ "camera { orthographic location <0,0,-3> look_at 0 right 1.6*x up 1.6*y }\n\
       light_source { <0, 100, 0> rgb 1 parallel point_at 0 }\n\
       box { <-50,-1,-0.5>, <50,1,0.5> " ^ clear
    ^ " interior { media { scattering { 1, <0.3, 0.6, 0.9> } method 2 samples 40 intervals 1 } } }\n"
  in
  let mc = render ~w:16 ~h:16 ~spp:256 ~depth:2 text and wh = Helpers.render_whitted ~width:16 ~height:16 text in
  for c = 0 to 2 do
    let r = channel_mean mc c /. channel_mean wh c in
    if Float.abs (r -. 0.25) > 0.25 *. 0.02 then Alcotest.failf "channel %d: mc / whitted %g, expected 0.25" c r
  done

(* Media inside glass: a glass sphere whose interior absorbs sigma is the
   glass sphere whose interior fades exponentially (fade_power 1001) by
   exp (-(1 - c) d / D) with 1 - c = sigma D: the same paths, the same
   light *)
let glass () =
  let sphere interior =
    header
    ^ "camera { location <0,0,-4> look_at 0 angle 40 }\n\
       sky_sphere { pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.6>] [1 rgb 1] } } }\n\
       plane { y, -1 pigment { checker rgb 0.8, rgb 0.2 } }\n\
       sphere { 0, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 " ^ interior ^ " } }\n"
  in
  let a = render ~w:24 ~h:24 ~spp:16 ~depth:16 (sphere "media { absorption <0.5, 0.2, 0> }") in
  let b = render ~w:24 ~h:24 ~spp:16 ~depth:16 (sphere "fade_distance 1 fade_power 1001 fade_color <0.5, 0.8, 1>") in
  let c = render ~w:24 ~h:24 ~spp:16 ~depth:16 (sphere "") in
  for y = 0 to 23 do
    for x = 0 to 23 do
      let r, g, bl = Helpers.pixel a x y and r', g', b' = Helpers.pixel b x y in
      if Float.abs (r -. r') +. Float.abs (g -. g') +. Float.abs (bl -. b') > 1e-9 *. (1. +. r +. g +. bl) then
        Alcotest.failf "pixel (%d,%d): media (%g, %g, %g), fade (%g, %g, %g)" x y r g bl r' g' b'
    done
  done;
  (* and the media do dim it: red, through the middle *)
  let r, _, _ = Helpers.pixel a 12 12 and r0, _, _ = Helpers.pixel c 12 12 in
  if not (r < 0.6 *. r0) then Alcotest.failf "the middle's red: %g with media, %g without" r r0

(* The phase functions' sampling: chi-square of the cosines drawn
   against each function's own integral over 40 bins; the density
   reported is the one drawn from (the sampled direction's, and
   integrating to 1 over the sphere); the value integrates to 1 too *)
let phase_sampling () =
  let md = Medium.get () in
  let d = Vec3.m () and wi = Vec3.m () in
  Vec3.set d 0.3 (-0.4) 0.866;
  Vec3.normalize_m d;
  let rng = Random.State.make [| 7 |] in
  List.iter
    (fun (what, (sc : Media.scattering)) ->
      (* integrals over the cosine *)
      let fine = 200_000 in
      let ph = ref 0. and pd = ref 0. in
      let bins = 40 in
      let expect = Array.make bins 0. in
      for i = 0 to fine - 1 do
        let c = -1. +. (2. *. (float i +. 0.5) /. float fine) in
        Medium.phase_at md sc c;
        ph := !ph +. md.n.ph;
        pd := !pd +. md.n.pdf;
        let k = Int.min (bins - 1) (int_of_float ((c +. 1.) /. 2. *. float bins)) in
        expect.(k) <- expect.(k) +. md.n.pdf
      done;
      let k = 2. *. Float.pi *. 2. /. float fine in
      if Float.abs ((!ph *. k) -. 1.) > 1e-4 then Alcotest.failf "%s: the phase function integrates to %g" what (!ph *. k);
      if Float.abs ((!pd *. k) -. 1.) > 1e-4 then Alcotest.failf "%s: the density integrates to %g" what (!pd *. k);
      let n = 100_000 in
      let seen = Array.make bins 0 in
      for _ = 1 to n do
        Medium.sample_phase md sc d (Random.State.float rng 1.) (Random.State.float rng 1.) wi;
        let c = Vec3.dot_m wi d in
        let pdf = md.n.pdf and w = md.n.ph /. md.n.pdf in
        Medium.phase_at md sc c;
        if Float.abs (md.n.pdf -. pdf) > 1e-6 *. pdf then
          Alcotest.failf "%s: density %g drawn, %g at its cosine %g" what pdf md.n.pdf c;
        if not (w > 0.9 && w < 1.1) then Alcotest.failf "%s: weight %g at %g" what w c;
        if (sc.kind = 1 || sc.kind = 5) && Float.abs (w -. 1.) > 1e-9 then Alcotest.failf "%s: weight %g" what w;
        let k = Int.max 0 (Int.min (bins - 1) (int_of_float ((c +. 1.) /. 2. *. float bins))) in
        seen.(k) <- seen.(k) + 1
      done;
      let chi = ref 0. in
      for k = 0 to bins - 1 do
        let e = expect.(k) /. !pd *. float n in
        chi := !chi +. (((float seen.(k) -. e) ** 2.) /. e)
      done;
      let p = Chi2.upper_tail ~df:(float (bins - 1)) !chi in
      if p < 1e-3 then Alcotest.failf "%s: chi-square %g, p %g" what !chi p)
    [
      ("isotropic", Media.scattering 1 Color.white);
      ("Mie hazy", Media.scattering 2 Color.white);
      ("Mie murky", Media.scattering 3 Color.white);
      ("Rayleigh", Media.scattering 4 Color.white);
      ("Henyey-Greenstein 0.8", { (Media.scattering 5 Color.white) with eccentricity = 0.8 });
      ("Henyey-Greenstein -0.3", { (Media.scattering 5 Color.white) with eccentricity = -0.3 });
    ]

(* A density's bound: the largest channel its entries take *)
let bounds () =
  let s =
    Helpers.compile_string
      (header
     ^ "sphere { 0, 1 " ^ clear
     ^ " interior { media { absorption <1, 2, 3> density { spherical color_map { [0 rgb 0] [0.5 rgb <0.5, 2, 1>] [1 rgb 1] } } \
        density { checker rgb 0.5, rgb <0.2, 0.1, 0.3> } } } }\n")
  in
  match s.objects.(0).interior.media with
  | [ m ] -> Alcotest.(check (float 1e-12)) "3 x 2 x 0.5" 3. (Media.majorant m)
  | _ -> Alcotest.fail "one medium"

(* fog, an atmosphere, interior media with and without densities,
   scattering and emitting, lit by point and area lights, an emissive
   sphere and the sky: a sample allocates nothing *)
let allocation () =
  let s =
    Helpers.compile_string
      (header
     ^ "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
        light_source { <-4, 6, -5>, rgb 1 media_attenuation on }\n\
        light_source { <3, 5, -3>, rgb 0.5 area_light <1, 0, 0>, <0, 0, 1>, 3, 3 }\n\
        background { rgb <0.4, 0.5, 0.7> }\n\
        fog { fog_type 2 distance 10 fog_offset 0.3 fog_alt 0.5 turbulence 0.3 color rgb 0.8 }\n\
        media { scattering { 2, 0.02 } absorption 0.01 }\n\
        plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }\n\
        sphere { <-1, 1, 0>, 1 " ^ clear
     ^ " interior { media { emission <1, 0.5, 0.2> scattering { 5, 0.5 eccentricity 0.3 } density { spherical } } } }\n\
        box { <0.5, 0, -1>, <2, 1.5, 0.5> " ^ clear
     ^ " interior { media { absorption <0.2, 0.5, 0.8> scattering { 3, 0.4 } } } }\n\
        sphere { <0, 0.5, -1.5>, 0.5 pigment { rgbf 1 } interior { ior 1.5 media { absorption 0.5 } } }\n\
        sphere { <2, 3, 1>, 0.3 pigment { rgb 1 } finish { emission 3 } }\n")
  in
  let img, words = Test_path.words_per_sample s in
  Alcotest.(check bool) "lit" true (mean img > 0.05);
  if words > 0.05 then Alcotest.failf "%.2f minor words per sample" words

(* A rainbow over an emitting wall seen by an orthographic camera (every
   ray along +z, so every pixel sees the same band of it): mc mode lays it
   over the light as whitted mode does, to 1e-12 *)
let rainbow () =
  let text =
    header
    ^ "camera { orthographic location <0,0,-1> look_at 0 right 2*x up 2*y }\n\
       plane { -z, -9 pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0 diffuse 0 emission 1 } }\n\
       rainbow { angle 35 width 10 distance 20 direction <0, -0.5735764, 0.8191520>\n\
         color_map { [0 rgbf <1, 0.3, 0.3, 0.4>] [1 rgbf <0.3, 0.3, 1, 0.4>] } }\n"
  in
  let wh = Helpers.render_whitted ~width:6 ~height:6 text in
  let r, g, b = Helpers.pixel wh 0 0 in
  (* the rainbow is there: the wall's light is changed *)
  if Float.abs (r -. 0.2) < 1e-3 && Float.abs (b -. 0.9) < 1e-3 then Alcotest.fail "whitted draws no rainbow here";
  every "whitted: one colour" wh (r, g, b) 1e-12;
  every "mc = whitted" (render ~w:6 ~h:6 ~spp:4 ~depth:4 text) (r, g, b) 1e-12

let tests =
  ( "mcmedia",
    [
      Alcotest.test_case "transmittance: exp(-sigma d), graded slabs (tracking, ratio tracking)" `Quick transmittance;
      Alcotest.test_case "emission: e (1 - exp(-sigma d)) / sigma, graded slabs" `Quick emission;
      Alcotest.test_case "white furnace: albedo 1 media of every phase function give 1" `Slow scattering_furnace;
      Alcotest.test_case "light sampling + MIS = phase sampling alone" `Slow nee_vs_phase;
      Alcotest.test_case "fog: T L + (1 - T) C, filter, transmit, ground fog = whitted" `Quick fog;
      Alcotest.test_case "a rainbow over a wall: mc = whitted" `Quick rainbow;
      Alcotest.test_case "absorption and emission: mc = whitted" `Quick vs_whitted;
      Alcotest.test_case "single scattering: a quarter of whitted's" `Quick single_scattering;
      Alcotest.test_case "absorbing media in glass = exponential fade" `Quick glass;
      Alcotest.test_case "phase sampling: chi-square, densities" `Quick phase_sampling;
      Alcotest.test_case "a density's majorant" `Quick bounds;
      Alcotest.test_case "an mc sample in fog and media allocates nothing" `Quick allocation;
    ] )
