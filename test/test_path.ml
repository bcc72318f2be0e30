(* Monte Carlo mode: physics with known answers (furnaces, an emitting
   enclosure), agreement with the Whitted mode where both are exact,
   agreement of NEE+MIS with BSDF-only sampling, convergence rate,
   determinism. Scenes are written in the scene language. *)
open Camlray

let render ?(nee = true) ?(domains = 1) ?(seed = 1) ~w ~h ~spp ~depth text =
  let t = Path.prepare ~nee (Helpers.compile_string text) in
  Render.image ~domains ~width:w ~height:h (Path.pixel t ~width:w ~height:h ~seed ~spp ~max_depth:depth)

let fold img f init =
  let acc = ref init in
  for y = 0 to Image.height img - 1 do
    for x = 0 to Image.width img - 1 do
      acc := f !acc x y (Image.get_r img x y, Image.get_g img x y, Image.get_b img x y)
    done
  done;
  !acc

let mean img =
  let s = fold img (fun a _ _ (r, g, b) -> a +. ((r +. g +. b) /. 3.)) 0. in
  s /. float (Image.width img * Image.height img)

let all_within what img expected tol =
  fold img
    (fun () x y (r, g, b) ->
      List.iter
        (fun v ->
          if Float.abs (v -. expected) > tol then
            Alcotest.failf "%s: pixel (%d,%d) is %g, expected %g +- %g" what x y v expected tol)
        [ r; g; b ])
    ()

(* root mean square difference of two images' channels *)
let rmse a b =
  let n = float (Image.width a * Image.height a * 3) in
  let s =
    fold a
      (fun acc x y (r, g, bl) ->
        let r', g', b' = Helpers.pixel b x y in
        acc +. ((r -. r') ** 2.) +. ((g -. g') ** 2.) +. ((bl -. b') ** 2.))
      0.
  in
  Float.sqrt (s /. n)

let header = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

(* The red mean of a 12x12 image's 6x6 central pixels (on the furnace's
   sphere): where lobes are chosen at random, one pixel is too noisy *)
let centre img =
  let s = ref 0. in
  for y = 3 to 8 do
    for x = 3 to 8 do
      let r, _, _ = Helpers.pixel img x y in
      s := !s +. r
    done
  done;
  !s /. 36.

(* Camera outside a unit sphere that fills the middle of the image. *)
let furnace finish =
  header ^ "camera { location <0,0,-3> look_at 0 angle 50 }\nbackground { rgb 1 }\n"
  ^ "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 " ^ finish ^ " } }\n"

let white_furnace () =
  (* albedo 1 under a uniform environment of radiance 1: every pixel 1 *)
  all_within "albedo 1" (render ~w:12 ~h:12 ~spp:4 ~depth:16 (furnace "diffuse 1")) 1. 0.01;
  (* albedo 0.5: light reflects once off a convex sphere, so 0.5 on the
     sphere and 1 around it; the centre pixel is on the sphere *)
  let img = render ~w:12 ~h:12 ~spp:4 ~depth:16 (furnace "diffuse 0.5") in
  let r, _, _ = Helpers.pixel img 6 6 and c, _, _ = Helpers.pixel img 0 0 in
  Alcotest.(check (float 0.005)) "albedo 0.5 on the sphere" 0.5 r;
  Alcotest.(check (float 0.)) "background" 1. c;
  (* a mix of diffuse 0.25 and a mirror 0.25 reflects 0.5 *)
  let img = render ~w:12 ~h:12 ~spp:256 ~depth:16 (furnace "diffuse 0.25 reflection 0.25") in
  Alcotest.(check (float 0.01)) "diffuse + mirror 0.5" 0.5 (centre img)

let glass_furnace () =
  (* a clear dielectric loses nothing: exact Fresnel splits, TIR and
     roulette must keep the mean at 1 *)
  let img =
    render ~w:12 ~h:12 ~spp:64 ~depth:64
      (furnace "diffuse 0 } pigment { rgbt <1,1,1,1> } interior { ior 1.5")
  in
  Alcotest.(check (float 0.01)) "mean" 1. (mean img);
  all_within "glass" img 1. 0.1

(* conserve_energy: a clear sphere (rgbt 1) that also reflects 0.5
   passes the other half under a uniform sky of 1 (2.5 without it); a
   refracting one keeps 1 through its Fresnel split, whose reflection
   stands for the finish's *)
let conserve_energy () =
  let clear fin = furnace ("diffuse 0 " ^ fin ^ " } pigment { rgbt 1 } interior { ior 1") in
  let on text = centre (render ~w:12 ~h:12 ~spp:256 ~depth:32 text) in
  Alcotest.(check (float 0.02)) "reflection 0.5, conserved" 1. (on (clear "reflection 0.5 conserve_energy"));
  (* without it light is made: 0.5 reflected, and all of it let in,
     where the far side lets all out and reflects 0.5 back in, again
     and again: 0.5 + 1 / (1 - 0.5) *)
  Alcotest.(check (float 0.05)) "not conserved" 2.5 (on (clear "reflection 0.5"));
  Alcotest.(check (float 0.02)) "refracting, conserved" 1.
    (on (furnace "diffuse 0 reflection 0.5 conserve_energy } pigment { rgbt 1 } interior { ior 1.5"))

(* A shadow ray meets a solid's interior_texture where it leaves it, as
   in whitted mode: the ground under a sphere that is clear outside lets
   through what its inside filters (none where the inside is opaque),
   against the same ground unshadowed; the sphere is not seen, and the
   light is a point: the light is direct *)
let interior_texture_shadow () =
  let ground sphere =
    let img =
      render ~w:3 ~h:3 ~spp:64 ~depth:4
        (header
        ^ "camera { location <0,5,-0.001> look_at <0,0,0> angle 5 }\nlight_source { <0,20,0>, rgb 1 }\n\
           plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.9 } }\n" ^ sphere)
    in
    Helpers.pixel img 1 1
  in
  let r0, g0, b0 = ground "" in
  let inside pig =
    ground
      ("sphere { <0,2,0>, 1 texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } } \
        interior_texture { pigment { " ^ pig ^ " } finish { ambient 0 diffuse 0 } } no_image }\n")
  in
  let r, g, b = inside "rgb <0.2,0.4,1>" in
  if r +. g +. b > 0.01 *. (r0 +. g0 +. b0) then Alcotest.failf "opaque inside: %g %g %g" r g b;
  let r, g, b = inside "rgbf <0.2,1,0.5,1>" in
  Alcotest.(check (float 0.01)) "filter red" 0.2 (r /. r0);
  Alcotest.(check (float 0.01)) "filter green" 1. (g /. g0);
  Alcotest.(check (float 0.01)) "filter blue" 0.5 (b /. b0)

(* A white diffuse sphere inside a clear hollow shell (ior 1) under a sky
   of radiance 1: every pixel 1. A path passing straight through the
   shell keeps the diffuse vertex's MIS weight; counted as a specular
   bounce, the sky behind the shell was counted by light sampling and by
   the path both (1.5 on the sphere). The same with an emissive sphere
   seen through the shell: light sampling through it, the path's weight
   kept, NEE+MIS = BSDF sampling alone. *)
let clear_shell () =
  let text =
    header ^ "camera { location <0,0,-4> look_at 0 angle 50 }\nbackground { rgb 1 }\n"
    ^ "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    ^ "sphere { 0, 1.5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }\n"
  in
  all_within "inside a clear shell" (render ~w:12 ~h:12 ~spp:16 ~depth:16 text) 1. 0.02;
  let text =
    header ^ "camera { location <0,0,-5> look_at 0 angle 50 }\n"
    ^ "sphere { 0, 1 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }\n"
    ^ "sphere { 0, 1.5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }\n"
    ^ "sphere { <1.2, 2.5, -1>, 0.4 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 5 } }\n"
  in
  let a = render ~w:16 ~h:16 ~spp:256 ~depth:8 text in
  let b = render ~nee:false ~seed:2 ~w:16 ~h:16 ~spp:1024 ~depth:8 text in
  let ma = mean a and mb = mean b in
  if Float.abs (ma -. mb) > 0.02 *. ma then Alcotest.failf "NEE+MIS %g vs BSDF only %g" ma mb

(* Inside a closed diffuse sphere of albedo a emitting Le, L = Le / (1 - a)
   (all bounces: depth 256, Russian roulette). *)
let enclosure a le expected tol () =
  let text =
    Printf.sprintf
      "%scamera { location <0,0,0> look_at z }\n\
       sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse %g emission %g } }\n"
      header a le
  in
  let img = render ~w:8 ~h:8 ~spp:64 ~depth:256 text in
  Alcotest.(check (float tol)) "radiance" expected (mean img)

(* Texture normals in mc mode: a strong [normal] tilts the shading
   normal far from the surface's, and directions sent below the surface
   are mirrored back up, so a white surface still reflects all it
   receives. A convex sphere of albedo 0.5 under a sky of radiance 1
   reflects once: 0.5 wherever it is. With BSDF sampling alone every
   sample weighs exactly the albedo, so every pixel inside the disc is
   0.5 (a sample dropped or lost below the surface would darken it). *)
let bumpy_finish a = Printf.sprintf "diffuse %g } normal { bumps 3 scale 0.05" a

let bumpy_furnace () =
  let inside img f =
    for y = 4 to 7 do
      for x = 4 to 7 do
        let r, g, b = Helpers.pixel img x y in
        f x y r;
        f x y g;
        f x y b
      done
    done
  in
  let img = render ~nee:false ~w:12 ~h:12 ~spp:16 ~depth:16 (furnace (bumpy_finish 0.5)) in
  inside img (fun x y v ->
      if Float.abs (v -. 0.5) > 1e-9 then Alcotest.failf "BSDF sampling: pixel (%d,%d) is %.12g, expected 0.5" x y v);
  (* albedo 1: the sky, everywhere *)
  all_within "albedo 1, bumps" (render ~nee:false ~w:12 ~h:12 ~spp:16 ~depth:16 (furnace (bumpy_finish 1.))) 1. 1e-9;
  (* light and BSDF sampling combined (the sky sampled about the
     surface's normal, the material about the shading one): the same
     mean, with noise (4 standard deviations) *)
  let img = render ~w:12 ~h:12 ~spp:256 ~depth:16 (furnace (bumpy_finish 0.5)) in
  let s = ref 0. in
  inside img (fun _ _ v -> s := !s +. v);
  Alcotest.(check (float 0.01)) "NEE + MIS: mean inside the disc" 0.5 (!s /. 48.)

(* The enclosure of albedo 0.5 emitting 0.5 (L = 1) with a bumpy inside:
   every bounce keeps half, at any depth *)
let bumpy_enclosure () =
  let text =
    header
    ^ "camera { location <0,0,0> look_at z }
       sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse 0.5 emission 0.5 }
      \  normal { bumps 3 scale 0.05 } }
"
  in
  let img = render ~w:8 ~h:8 ~spp:64 ~depth:256 text in
  Alcotest.(check (float 0.02)) "radiance" 1. (mean img)

(* The pixel integral of a whitted render: [k] x [k] samples per pixel,
   box-filtered *)
let whitted_boxed ~w ~h ~k text =
  let big = Helpers.render_whitted ~width:(k * w) ~height:(k * h) text in
  let out = Image.create w h in
  let n = float (k * k) in
  for y = 0 to h - 1 do
    for x = 0 to w - 1 do
      let r = ref 0. and g = ref 0. and b = ref 0. in
      for j = 0 to k - 1 do
        for i = 0 to k - 1 do
          let r', g', b' = Helpers.pixel big ((k * x) + i) ((k * y) + j) in
          r := !r +. (r' /. n);
          g := !g +. (g' /. n);
          b := !b +. (b' /. n)
        done
      done;
      Image.set out x y !r !g !b
    done
  done;
  out

(* PSNR of linear images, peak 1 *)
let psnr a b =
  let e = rmse a b in
  20. *. Float.log10 (1. /. e)

(* A bumpy diffuse plane seen from above under one point light, black
   sky, ambient 0: light reaches each point once, a c (ns . l) in both
   modes (the lights are high, so no shading normal here turns from
   the light or the eye, where the modes' rules differ). mc must match
   whitted's picture of the bumps, not the smooth plane's. *)
let bumpy_plane normal =
  header
  ^ "camera { location <0, 3, -1> look_at 0 angle 40 }
     light_source { <2, 5, -2> color rgb <1, 0.9, 0.8> }
     light_source { <-3, 4, 1> color rgb 0.4 }
     plane { y, 0 pigment { rgb <0.9, 0.7, 0.5> } finish { ambient 0 diffuse 0.8 } " ^ normal ^ " }
"

let bumps_vs_whitted () =
  let w = 32 and h = 24 in
  let text = bumpy_plane "normal { bumps 0.6 scale 0.4 }" in
  let mc = render ~w ~h ~spp:64 ~depth:4 text and wh = whitted_boxed ~w ~h ~k:8 text in
  let smooth = render ~w ~h ~spp:64 ~depth:4 (bumpy_plane "") in
  let m1 = mean mc and m2 = mean wh and m0 = mean smooth in
  let p = psnr mc wh and p0 = psnr smooth wh in
  if Sys.getenv_opt "MC_VERBOSE" <> None then
    Printf.printf "means: mc %g whitted %g smooth %g; PSNR mc %g smooth %g\n" m1 m2 m0 p p0;
  if Float.abs (m1 -. m2) > 0.01 *. m2 then Alcotest.failf "image means: mc %g, whitted %g" m1 m2;
  if p < 40. then Alcotest.failf "mc against whitted: PSNR %.1f dB (at least 40)" p;
  (* the smooth plane is far from both *)
  if p0 > 30. then Alcotest.failf "smooth plane against bumpy whitted: PSNR %.1f dB (at most 30)" p0

(* One point light, one diffuse sphere, ambient 0, black background: one
   bounce only, so both modes compute a c cos(theta) exactly; a spotlight
   with distance fade and a parallel light also. *)
let vs_whitted () =
  let text =
    header
    ^ "camera { location <0,0,-4> look_at 0 angle 40 }\n\
       light_source { <-3, 4, -4> color rgb <1, 0.8, 0.6> }\n\
       light_source { <3, 1, -3> color rgb 2 spotlight point_at 0 radius 10 falloff 20\n\
      \  fade_distance 3 fade_power 2 }\n\
       light_source { <0, 5, -5> color rgb 0.3 parallel point_at 0 }\n\
       sphere { 0, 1 pigment { rgb <0.9, 0.5, 0.2> } finish { ambient 0 diffuse 0.8 } }\n"
  in
  let w = 24 and h = 24 in
  let mc = render ~w ~h ~spp:16 ~depth:16 text in
  (* whitted at 4x4 samples per pixel, box-filtered: the pixel integral *)
  let big = Helpers.render_whitted ~width:(4 * w) ~height:(4 * h) text in
  let wh = Image.create w h in
  for y = 0 to h - 1 do
    for x = 0 to w - 1 do
      let r = ref 0. and g = ref 0. and b = ref 0. in
      for j = 0 to 3 do
        for i = 0 to 3 do
          let r', g', b' = Helpers.pixel big ((4 * x) + i) ((4 * y) + j) in
          r := !r +. (r' /. 16.);
          g := !g +. (g' /. 16.);
          b := !b +. (b' /. 16.)
        done
      done;
      Image.set wh x y !r !g !b
    done
  done;
  let m1 = mean mc and m2 = mean wh in
  if Float.abs (m1 -. m2) > 0.01 *. m2 then Alcotest.failf "image means: mc %g, whitted %g" m1 m2;
  (* pixels well inside the disc (no edge inside the pixel): within 2% *)
  fold wh
    (fun () x y (r, g, b) ->
      let dx = float x +. 0.5 -. 12. and dy = float y +. 0.5 -. 12. in
      if Float.sqrt ((dx *. dx) +. (dy *. dy)) < 6. then
        let r', g', b' = Helpers.pixel mc x y in
        List.iter2
          (fun a b ->
            if Float.abs (a -. b) > 0.02 *. Float.max b 0.05 then
              Alcotest.failf "pixel (%d,%d): mc %g, whitted %g" x y a b)
          [ r; g; b ] [ r'; g'; b' ])
    ()

(* A small emissive sphere over a diffuse floor and a glossy sphere: no
   delta lights, so BSDF sampling alone sees all the light. *)
let small_emitter =
  header
  ^ "camera { location <0,1.5,-4> look_at <0,0.5,0> angle 50 }\n\
     sphere { <1, 2.2, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 8 } }\n\
     plane { y, 0 pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }\n\
     sphere { <-0.5, 0.7, 0.5>, 0.7 pigment { rgb <0.8,0.3,0.2> }\n\
    \  finish { ambient 0 diffuse 0.6 specular 0.4 roughness 0.05 } }\n\
     background { rgb 0.05 }\n"

let nee_vs_bsdf () =
  let a = render ~w:16 ~h:16 ~spp:256 ~depth:8 small_emitter in
  let b = render ~nee:false ~seed:2 ~w:16 ~h:16 ~spp:1024 ~depth:8 small_emitter in
  let ma = mean a and mb = mean b in
  if Float.abs (ma -. mb) > 0.02 *. ma then Alcotest.failf "NEE+MIS %g vs BSDF only %g" ma mb

(* Only bounded estimators here (diffuse surfaces, a sky and a sphere
   light), so that the sample RMSE is a stable measure; spp values that are
   not squares, so pixel positions are not stratified either and every
   sample is independent: RMSE must fall as spp^-1/2. *)
let lambert_scene =
  header
  ^ "camera { location <0,1.5,-4> look_at <0,0.5,0> angle 50 }\n\
     sphere { <1, 2.2, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 4 } }\n\
     plane { y, 0 pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }\n\
     sphere { <-0.5, 0.7, 0.5>, 0.7 pigment { rgb <0.8,0.3,0.2> } finish { ambient 0 diffuse 1 } }\n\
     background { rgb <0.3, 0.4, 0.5> }\n"

let convergence () =
  let w = 12 and h = 12 in
  let reference = render ~seed:1000 ~w ~h ~spp:4096 ~depth:8 lambert_scene in
  let spps = [ 2; 8; 32; 128 ] in
  let pts =
    List.map
      (fun spp ->
        (* mean squared error over four seeds *)
        let mse =
          List.fold_left
            (fun a seed -> a +. (rmse (render ~seed ~w ~h ~spp ~depth:8 lambert_scene) reference ** 2.))
            0. [ 7; 8; 9; 10 ]
        in
        let e = Float.sqrt (mse /. 4.) in
        if Sys.getenv_opt "MC_VERBOSE" <> None then Printf.printf "spp %d rmse %g\n%!" spp e;
        (Float.log (float spp), Float.log e))
      spps
  in
  let n = float (List.length pts) in
  let sx = List.fold_left (fun a (x, _) -> a +. x) 0. pts
  and sy = List.fold_left (fun a (_, y) -> a +. y) 0. pts in
  let sxx = List.fold_left (fun a (x, _) -> a +. (x *. x)) 0. pts
  and sxy = List.fold_left (fun a (x, y) -> a +. (x *. y)) 0. pts in
  let slope = ((n *. sxy) -. (sx *. sy)) /. ((n *. sxx) -. (sx *. sx)) in
  if Sys.getenv_opt "MC_VERBOSE" <> None then Printf.printf "slope %g\n" slope;
  if Float.abs (slope +. 0.5) > 0.1 then Alcotest.failf "RMSE ~ spp^%g, expected spp^-0.5" slope

let domains () =
  let text =
    small_emitter
    ^ "sphere { <1.2, 0.5, -0.5>, 0.5 pigment { rgbf <1,1,1,0.9> } interior { ior 1.5 } }\n"
  in
  let a = render ~domains:1 ~w:20 ~h:15 ~spp:4 ~depth:8 text in
  let b = render ~domains:2 ~w:20 ~h:15 ~spp:4 ~depth:8 text in
  fold a (fun () x y c -> if c <> Helpers.pixel b x y then Alcotest.failf "pixel (%d,%d)" x y) ()

(* Depth of field: every lens sample through a screen point meets the same
   point of the focal plane; the lens has radius aperture / 4 (POV-Ray). *)
let lens () =
  let s =
    Helpers.compile_string
      "#version 3.7;\ncamera { location <0,0,-5> look_at 0 aperture 2 focal_point <0,0,1> blur_samples 8 }\n"
  in
  let cam = s.camera in
  let pinhole = Camera.ray cam 0.2 (-0.1) in
  let tf = 6. /. pinhole.dir.z in
  let focus = Ray.at pinhole tf in
  let far = ref 0. in
  for i = 0 to 9 do
    for j = 0 to 9 do
      let r = Camera.ray_lens cam 0.2 (-0.1) (float i /. 9. *. 0.999999) (float j /. 10.) in
      let off = Vec3.dist r.origin cam.location in
      far := Float.max !far off;
      if off > 0.5 +. 1e-12 then Alcotest.failf "lens offset %g > aperture/4" off;
      let t = (1. -. r.origin.z) /. r.dir.z in
      let p = Ray.at r t in
      if Vec3.dist p focus > 1e-9 then Alcotest.failf "not in focus: %s" (Vec3.to_string p)
    done
  done;
  Alcotest.(check (float 1e-3)) "lens radius" 0.5 !far

(* POV's area light as a rectangle of fall-off-free point lights: over a
   Lambertian plane at height h below its centre, the radiance is
   a c <cos theta> (the mean of cos over the rectangle), by quadrature. *)
let area_light () =
  let s =
    Helpers.compile_string
      "#version 3.7;\nplane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.5 } }\n"
  in
  let h = 1. and side = 2. in
  let light = Light.point (Vec3.make 0. h 0.) (Color.gray 1.) in
  let area =
    Emitter.Area { light; area = Light.area (Vec3.make side 0. 0.) (Vec3.make 0. 0. side) 2 2 }
  in
  let t = Path.prepare ~extra:[ area ] s in
  let n = 20000 in
  let sum = ref 0. in
  for k = 0 to n - 1 do
    let sampler = Sampler.create ~seed:3 ~pixel:0 ~sample:k in
    let c = Path.li t sampler ~max_depth:1 (Ray.make (Vec3.make 0. 2. 0.) (Vec3.neg Vec3.unit_y)) in
    sum := !sum +. c.r
  done;
  let q = 400 in
  let mean_cos = ref 0. in
  for i = 0 to q - 1 do
    for j = 0 to q - 1 do
      let x = side *. (((float i +. 0.5) /. float q) -. 0.5)
      and z = side *. (((float j +. 0.5) /. float q) -. 0.5) in
      mean_cos := !mean_cos +. (h /. Float.sqrt ((h *. h) +. (x *. x) +. (z *. z)))
    done
  done;
  let expected = 0.5 *. !mean_cos /. float (q * q) in
  Alcotest.(check (float (0.01 *. expected))) "radiance" expected (!sum /. float n)

(* An area_light read from a scene becomes an emitting rectangle whose
   far-field irradiance is that of the point light of the same colour at
   its centre: far above a Lambertian plane (albedo a = 0.5) the radiance
   is a c cos theta = 0.5 c, as in the whitted mode; at 2 units the
   rectangle (4 x 4) gives less (the mean of cos over it), and a circular
   one of the same axes sits between the two. *)
let area_light_from_scene () =
  let radiance ?(circular = "") h =
    let s =
      Helpers.compile_string
        (Printf.sprintf
           "#version 3.7;\nplane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.5 } }\n\
            light_source { <0,%g,0> rgb <1,0.5,0.25> area_light <4,0,0>, <0,0,4>, 5, 5 %s }\n"
           h circular)
    in
    (match s.lights with
     | [| { area = Some _; _ } |] -> ()
     | _ -> Alcotest.fail "expected one area light");
    let t = Path.prepare s in
    let n = 4000 in
    let sum = ref Color.black in
    for k = 0 to n - 1 do
      let sampler = Sampler.create ~seed:5 ~pixel:0 ~sample:k in
      let c =
        Path.li t sampler ~max_depth:1 (Ray.make (Vec3.make 0.5 0.5 0.) (Vec3.neg Vec3.unit_y))
      in
      sum := Color.add !sum c
    done;
    Color.scale (1. /. float n) !sum
  in
  let far = radiance 1000. in
  Alcotest.(check (float 1e-4)) "far: red" 0.5 far.r;
  Alcotest.(check (float 1e-4)) "far: green" 0.25 far.g;
  Alcotest.(check (float 1e-4)) "far: blue" 0.125 far.b;
  let near = radiance 2. and disc = radiance ~circular:"circular" 2. in
  if not (near.r < 0.47 && near.r < disc.r && disc.r < 0.5) then
    Alcotest.failf "near field: square %g, disc %g, point 0.5" near.r disc.r

(* A sky_sphere is the environment light: a Lambertian plane (albedo a)
   under a sky whose radiance rises as cos theta (gradient y from 0 at
   the horizon to 1 at the zenith) receives E = 2 pi / 3, so its radiance
   is a E / pi = 2a/3; a ray that escapes sees the sky itself. *)
let sky_environment () =
  let s =
    Helpers.compile_string
      "#version 3.7;\nbackground { rgb <5,0,0> }\n\
       sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }\n\
       plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.5 } }\n"
  in
  let t = Path.prepare s in
  let mean ~nee ray =
    let t = if nee then t else Path.prepare ~nee:false s in
    let n = 20000 in
    let sum = ref 0. in
    for k = 0 to n - 1 do
      let sampler = Sampler.create ~seed:9 ~pixel:1 ~sample:k in
      sum := !sum +. (Path.li t sampler ~max_depth:4 ray).r
    done;
    !sum /. float n
  in
  let down = Ray.make (Vec3.make 0. 1. 0.) (Vec3.neg Vec3.unit_y) in
  Alcotest.(check (float 0.01)) "plane, light sampling" (1. /. 3.) (mean ~nee:true down);
  Alcotest.(check (float 0.01)) "plane, material sampling" (1. /. 3.) (mean ~nee:false down);
  let up = Ray.make (Vec3.make 0. 1. 0.) (Vec3.normalize (Vec3.make 0. 1. 1.)) in
  Alcotest.(check (float 1e-9)) "escaping ray sees the sky" (Float.sqrt 0.5) (mean ~nee:true up)

(* The Monte Carlo scenes of test/mc render (tiny, 2 spp) to finite,
   non-negative pixels, and not all black. *)
let mc_scenes () =
  let dir = Filename.concat (Filename.dirname (Helpers.scenes_dir ())) "test/mc" in
  let files = Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".scn") in
  if List.length files < 4 then Alcotest.failf "expected the mc scenes in %s" dir;
  List.iter
    (fun f ->
      let text = In_channel.with_open_bin (Filename.concat dir f) In_channel.input_all in
      let img = render ~w:16 ~h:9 ~spp:2 ~depth:16 text in
      fold img
        (fun () x y (r, g, b) ->
          List.iter
            (fun v ->
              if not (Float.is_finite v && v >= 0.) then Alcotest.failf "%s (%d,%d): %g" f x y v)
            [ r; g; b ])
        ();
      if mean img <= 0. then Alcotest.failf "%s is black" f)
    files

(* The image of a 48x36 one-domain render at 4 spp as [camlray render]
   runs it ([Render.image_into]), the second of two (the first makes the
   domain's scratch), and the minor words per sample it took *)
let words_per_sample s =
  let width = 48 and height = 36 and spp = 4 in
  let pixel = Path.pixel_into (Path.prepare s) ~width ~height ~seed:1 ~spp ~max_depth:8 in
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  let before = Gc.minor_words () in
  let img = Render.image_into ~domains:1 ~width ~height pixel in
  (img, (Gc.minor_words () -. before) /. float_of_int (width * height * spp))

(* A sample walks its path in per-domain records: solid pigments, a
   point light and the background, matte, metal and glass surfaces,
   spheres, a transformed sphere, a box and a plane, nothing allocated.
   Minor words per sample over a one-domain render as [camlray render]
   runs it ([Render.image_into]); the tiles' records are the slack. *)
let allocation () =
  let s =
    Helpers.compile_string
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       light_source { <-4, 6, -5>, rgb 1 }\n\
       background { rgb <0.4, 0.5, 0.7> }\n\
       plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }\n\
       sphere { <-1, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.5 specular 0.3 } }\n\
       sphere { <1.2, 0.8, 0.5>, 0.8 pigment { rgb 0.9 } finish { reflection 0.6 metallic } }\n\
       sphere { <0, 0.5, -1.5>, 0.5 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }\n\
       sphere { 0, 1 scale <0.3, 0.6, 0.3> translate <2, 0.6, -1> pigment { rgb <0.2, 0.7, 0.3> } }\n\
       box { <-0.5, 0, -2>, <0.5, 0.6, -1.4> rotate y*20 pigment { rgb <0.2, 0.3, 0.8> } }"
  in
  let img, words = words_per_sample s in
  (* the picture is not black: paths found light *)
  Alcotest.(check bool) "lit" true (mean img > 0.05);
  if words > 0.1 then Alcotest.failf "%.2f minor words per sample (at most 0.1)" words;
  (* area lights, square and oriented disc, one with a looks_like shape
     (crossed by every shadow ray towards it, casting none) *)
  let s =
    Helpers.compile_string
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       light_source { <0, 4, 0>, rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4\n\
         looks_like { box { <-0.5, -0.01, -0.5>, <0.5, 0.01, 0.5> pigment { rgb 1 } finish { emission 1 } } } }\n\
       light_source { <-4, 5, -3>, rgb 0.5 area_light <1, 0, 0>, <0, 1, 0>, 3, 3 circular orient }\n\
       plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }\n\
       sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } }"
  in
  let img, words = words_per_sample s in
  Alcotest.(check bool) "lit by area lights" true (mean img > 0.05);
  if words > 0.1 then Alcotest.failf "%.2f minor words per sample with area lights (at most 0.1)" words;
  (* pattern pigments (a map, blocks, turbulence) and a sky_sphere as the
     environment light, seen and sampled *)
  let s =
    Helpers.compile_string
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.7>] [1 rgb <0.3, 0.4, 0.8>] } } }\n\
       plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 rotate y*30 } }\n\
       sphere { <0, 1, 0>, 1 pigment { bozo turbulence 0.4 color_map { [0 rgb <0.8, 0.3, 0.2>] [1 rgb 0.9] } } }\n\
       sphere { <1.5, 0.5, -1>, 0.5 pigment { hexagon rgb 1, rgb 0.5, rgb <0.2, 0.6, 0.3> scale 0.2 } }"
  in
  let img, words = words_per_sample s in
  Alcotest.(check bool) "lit by the sky" true (mean img > 0.05);
  if words > 0.1 then Alcotest.failf "%.2f minor words per sample with patterns and a sky (at most 0.1)" words;
  (* texture normals: shading normals on matte, phong, metal and glass
     surfaces, a normal_map and a uv-mapped normal *)
  let s =
    Helpers.compile_string
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       light_source { <-4, 6, -5>, rgb 1 }\n\
       background { rgb <0.4, 0.5, 0.7> }\n\
       plane { y, 0 pigment { rgb 0.8 } normal { bumps 0.8 scale 0.2 } }\n\
       sphere { <-1, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } normal { ripples 1 scale 0.3 } finish { phong 0.5 } }\n\
       sphere { <1.2, 0.8, 0.5>, 0.8 pigment { rgb 0.9 } normal { dents 2 scale 0.2 }\n\
      \  finish { reflection 0.6 metallic specular 0.5 } }\n\
       sphere { <0, 0.5, -1.5>, 0.5 pigment { rgbf <1, 1, 1, 0.9> } normal { bumps 0.5 scale 0.1 } interior { ior 1.5 } }\n\
       sphere { <2, 0.5, -1>, 0.5 pigment { rgb 0.7 }\n\
      \  normal { gradient x normal_map { [0 bumps 0.5 scale 0.1] [1 wrinkles 1 scale 0.2] } } }\n\
       sphere { <-2, 0.5, -1>, 0.5 uv_mapping pigment { rgb 0.7 } normal { quilted 1 scale 0.1 } }"
  in
  let img, words = words_per_sample s in
  Alcotest.(check bool) "lit, with normals" true (mean img > 0.05);
  if words > 0.1 then Alcotest.failf "%.2f minor words per sample with texture normals (at most 0.1)" words
  ;
  (* glowing spheres sampled as lights: from outside (the cone) and from
     inside one (by area), patterned emission (each sample once cost 48
     words: vectors, an option, a hit record) *)
  let s =
    Helpers.compile_string
      "camera { location <0, 2, -6> look_at <0, 0.8, 0> }\n\
       plane { y, 0 pigment { rgb 0.8 } }\n\
       sphere { <-1.5, 2.5, 0>, 0.5 pigment { checker rgb 1, rgb 0.5 scale 0.2 } finish { emission 4 diffuse 0 } }\n\
       sphere { 0, 1 scale 0.4 translate <1.5, 2, 0> pigment { rgb <1, 0.8, 0.6> } finish { emission 3 diffuse 0 } }\n\
       sphere { 0, 20 hollow pigment { rgbf <1, 1, 1, 0.95> } finish { emission 0.05 diffuse 0 } }\n\
       sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.5 } }"
  in
  let img, words = words_per_sample s in
  Alcotest.(check bool) "lit by glowing spheres" true (mean img > 0.05);
  if words > 0.1 then Alcotest.failf "%.2f minor words per sample with glowing spheres (at most 0.1)" words

(* The in-place sampling of a glowing sphere and its pdf give the value
   forms' numbers bit for bit, from outside the sphere and inside it *)
let sphere_emitter_in_place =
  QCheck.Test.make ~count:2000 ~name:"glowing sphere: sample_into and pdf_m = sample and pdf, bit for bit"
    QCheck.(
      pair
        (quad (float_range (-3.) 3.) (float_range (-3.) 3.) (float_range (-3.) 3.) (float_range 0.1 2.))
        (pair (float_range 0. 1.) (float_range 0. 1.)))
    (fun ((x, y, z, r), (u, v)) ->
      let center = Vec3.make 0.3 (-0.2) 0.5 in
      let obj = Object.make (Shape.sphere center r) in
      let e = Emitter.Sphere { obj; center; radius = r } in
      let p = Vec3.make x y z in
      let pm = Vec3.m () in
      Vec3.load pm p;
      let out = Emitter.sampled () in
      let same a b = Int64.equal (Int64.bits_of_float a) (Int64.bits_of_float b) in
      match (Emitter.sample e p u v, Emitter.sample_into e pm u v out) with
      | None, false -> true
      | Some a, true ->
          let q = Vec3.madd p a.dist a.wi in
          let qm = Vec3.m () and nm = Vec3.m () in
          Vec3.load qm q;
          let nq = Vec3.normalize (Vec3.sub q center) in
          Vec3.load nm nq;
          same a.wi.x out.wi.mx && same a.wi.y out.wi.my && same a.wi.z out.wi.mz
          && same a.dist out.n.dist && same a.pdf out.n.pdf
          && same (Emitter.pdf e p q nq) (Emitter.pdf_m e pm qm nm)
      | _ -> false)

(* light_group in mc mode: next-event estimation lights a surface by its
   own light set only, as whitted mode (and POV-Ray) does. Three spheres
   far apart in the dark, lit from the eye: the one in a group sees its
   red light only (whitted: 0.6 x the cosine), the one outside the blue
   global light only, the one with global_lights on both. The pixels
   agree with whitted mode's to 1% (what the spheres send each other is
   the difference). *)
let light_group () =
  let text =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 ambient_light 0 }\n\
     camera { orthographic location <0,0,-10> look_at 0 right 12*x up 3*y }\n\
     #default { finish { ambient 0 diffuse 0.6 } }\n\
     light_source { <0.125,-0.125,-1000> rgb <0,0,1> }\n\
     light_group { light_source { <-3.875,-0.125,-1000> rgb <1,0,0> } sphere { <-3.875,-0.125,0>, 1.4 pigment { rgb 1 } } }\n\
     light_group { light_source { <0.125,-0.125,-1000> rgb <0,1,0> } sphere { <0.125,-0.125,0>, 1.4 pigment { rgb 1 } } global_lights on }\n\
     sphere { <4.125,-0.125,0>, 1.4 pigment { rgb 1 } }\n"
  in
  (* the spheres' centres are pixel centres: the cosine is about flat
     over the pixel mc mode spreads its samples across *)
  let mc = render ~w:48 ~h:12 ~spp:16 ~depth:3 text in
  let wh = Helpers.render_whitted ~width:48 ~height:12 text in
  List.iter
    (fun (x, what, (er, eg, eb)) ->
      let r, g, b = Helpers.pixel mc x 6 and wr, wg, wb = Helpers.pixel wh x 6 in
      List.iter
        (fun (name, v, w, e) ->
          if Float.abs (v -. w) > 0.01 *. Float.max w 0.05 then
            Alcotest.failf "%s (%s): mc %g, whitted %g" what name v w;
          if (e = 0.) <> (w = 0.) then Alcotest.failf "%s (%s): whitted %g" what name w)
        [ ("red", r, wr, er); ("green", g, wg, eg); ("blue", b, wb, eb) ])
    [ (8, "in a group", (1., 0., 0.)); (24, "global_lights on", (0., 1., 1.)); (40, "outside", (0., 0., 1.)) ]

(* A cylinder light and a projected_through light in mc mode: delta
   lights, the beam's fall-off across its axis and the object as a
   condition on what the light sees (next-event estimation), the same as
   whitted mode's (and POV-Ray's). A plane seen head on, black sky, one
   bounce: each pixel's mean is the whitted pixel integral; a blocker
   between the projected object and its light casts no shadow, one
   before it does. *)
let cylinder_projected () =
  let text =
    header
    ^ "camera { orthographic location <0,0,-10> look_at 0 right 8*x up 4*y }\n\
       #default { finish { ambient 0 diffuse 0.8 } }\n\
       light_source { <-2,0,-5> rgb <1,0.6,0.3> cylinder point_at <-2,0,0> radius 0.5 falloff 1.5 tightness 1 }\n\
       light_source { <2,0,-5> rgb <0.3,0.6,1> projected_through { box { <1.5,-0.5,-2.1>, <2.5,0.5,-1.9> } } }\n\
       box { <1.8,-0.2,-3.1>, <2.2,0.2,-2.9> no_image }\n\
       box { <2.4,-0.3,-1.1>, <2.7,0.3,-0.9> no_image }\n\
       plane { z, 0 pigment { rgb 1 } }\n"
  in
  let w = 32 and h = 16 in
  let mc = render ~w ~h ~spp:16 ~depth:4 text and wh = whitted_boxed ~w ~h ~k:4 text in
  let m1 = mean mc and m2 = mean wh in
  if m2 < 0.05 then Alcotest.failf "whitted too dark: %g" m2;
  if Float.abs (m1 -. m2) > 0.02 *. m2 then Alcotest.failf "image means: mc %g, whitted %g" m1 m2;
  let p = psnr mc wh in
  if p < 35. then Alcotest.failf "mc against whitted: PSNR %.1f dB (at least 35)" p;
  (* pixel x covers [(x - 16) / 4, (x - 15) / 4]: the window is seen on
     the plane over [1.17, 2.83], the near blocker would shade [1.5,
     2.5], the far one shades [2.5, 2.875] *)
  let lit x = let _, _, b = Helpers.pixel mc x 8 in b in
  if lit 23 < 0.7 then Alcotest.failf "through the window, behind the near blocker: %g" (lit 23);
  if lit 26 > 1e-9 then Alcotest.failf "in the far blocker's shadow: %g" (lit 26)

(* POV-Ray's shadow tolerance in mc mode too (test_light has whitted
   mode's): a ceiling crossed within 1e-3 of the point light hides
   nothing, one crossed 0.002 sqrt 2 short of it hides the light; direct
   light only *)
let shadow_tolerance () =
  let at ceiling =
    let img =
      render ~w:1 ~h:1 ~spp:4 ~depth:1
        (Printf.sprintf
           "camera { location 0 look_at z }\n\
            light_source { <0,5,-4>, rgb 1 }\n\
            plane { y, %s pigment { rgb 1 } }\n\
            plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
           ceiling)
    in
    Image.get_r img 0 0
  in
  let open_sky = at "100" in
  if not (open_sky > 0.01) then Alcotest.failf "no ceiling: %g" open_sky;
  Scn.close ~eps:1e-12 "a ceiling 0.0004 under the light" open_sky (at "4.9996");
  Scn.close ~eps:1e-12 "a ceiling 0.002 under the light" 0. (at "4.998")

let tests =
  ( "path",
    [
      Alcotest.test_case "shadow tolerance: nothing within 1e-3 of the light hides it" `Quick shadow_tolerance;
      Alcotest.test_case "white furnace: albedo 1 -> 1, 0.5 -> 0.5, diffuse+mirror mix" `Quick
        white_furnace;
      Alcotest.test_case "glass furnace: a clear dielectric keeps radiance 1" `Quick glass_furnace;
      Alcotest.test_case "conserve_energy: a clear mirror sphere keeps radiance 1" `Quick conserve_energy;
      Alcotest.test_case "shadow rays meet the interior_texture where they leave a solid" `Quick interior_texture_shadow;
      Alcotest.test_case "a clear (ior 1) shell: the sky and a sphere light counted once" `Quick clear_shell;
      Alcotest.test_case "enclosure a=0.5 Le=0.5 -> 1" `Quick (enclosure 0.5 0.5 1. 0.02);
      Alcotest.test_case "enclosure a=0.9 Le=0.5 -> 5" `Quick (enclosure 0.9 0.5 5. 0.15);
      Alcotest.test_case "one light, one diffuse sphere: mc = whitted" `Quick vs_whitted;
      Alcotest.test_case "bumpy furnace: a normal loses no light (0.5 -> 0.5, 1 -> 1)" `Quick bumpy_furnace;
      Alcotest.test_case "bumpy enclosure a=0.5 Le=0.5 -> 1" `Quick bumpy_enclosure;
      Alcotest.test_case "bumpy plane, point lights: mc = whitted, not the smooth plane" `Quick bumps_vs_whitted;
      Alcotest.test_case "NEE+MIS and BSDF-only sampling agree" `Quick nee_vs_bsdf;
      Alcotest.test_case "RMSE falls as spp^-1/2" `Quick convergence;
      Alcotest.test_case "1 and 2 domains: identical images" `Quick domains;
      Alcotest.test_case "depth of field: focal plane and lens radius" `Quick lens;
    Alcotest.test_case "sky_sphere as the environment light" `Quick sky_environment;
    Alcotest.test_case "area light from a scene: far field = point light" `Quick area_light_from_scene;
    Alcotest.test_case "area light: a c <cos> over a plane" `Quick area_light;
    Alcotest.test_case "light_group: each surface by its light set" `Quick light_group;
    Alcotest.test_case "cylinder and projected_through lights: mc = whitted" `Quick cylinder_projected;
      Alcotest.test_case "test/mc scenes render" `Quick mc_scenes;
      Alcotest.test_case "a sample allocates nothing (point, area and sphere lights, normals)" `Quick allocation;
      QCheck_alcotest.to_alcotest sphere_emitter_in_place;
    ] )
