(* POV-Ray's radiosity in whitted mode: its settings as parsed, closed
   forms of the gathered light, the gather directions, and renders that
   do not depend on the domains. *)
open Camlray

let settings ?raw src =
  match (Scn.compile ?raw src).settings.radiosity with
  | Some r -> r
  | None -> Alcotest.fail "no radiosity in the scene's settings"

let same_image (a : Image.t) (b : Image.t) =
  let ok = ref true in
  for y = 0 to Image.height a - 1 do
    for x = 0 to Image.width a - 1 do
      if Image.get_r a x y <> Image.get_r b x y || Image.get_g a x y <> Image.get_g b x y
         || Image.get_b a x y <> Image.get_b b x y
      then ok := false
    done
  done;
  !ok

let defaults () =
  let r = settings "global_settings { radiosity { } }" in
  Alcotest.(check int) "count" 35 r.count;
  Alcotest.(check int) "recursion_limit" 2 r.recursion_limit;
  Alcotest.(check int) "nearest_count" 5 r.nearest_count;
  Scn.close "brightness" 1. r.brightness;
  Scn.close "error_bound" 1.8 r.error_bound;
  Scn.close "gray_threshold" 0. r.gray_threshold;
  Scn.close "pretrace_start" 0.08 r.pretrace_start;
  Scn.close "pretrace_end" 0.04 r.pretrace_end;
  Scn.close "low_error_factor" 0.5 r.low_error_factor;
  Scn.close "minimum_reuse" 0.015 r.minimum_reuse;
  Scn.close "maximum_reuse" 0.2 r.maximum_reuse;
  Scn.close "adc_bailout" 0.01 r.adc_bailout;
  Alcotest.(check bool) "max_sample off" true (r.max_sample <= 0.);
  Alcotest.(check bool) "normal, media, always_sample off" false (r.normal || r.media || r.always_sample);
  Alcotest.(check bool) "3.7 drops ambient" false r.keep_ambient;
  let r =
    settings
      "global_settings { radiosity { count 80, 1000 recursion_limit 3 brightness 0.7 error_bound 0.5 nearest_count 8 \
       gray_threshold 0.2 pretrace_start 0.1 pretrace_end 0.01 low_error_factor 0.6 minimum_reuse 0.01 maximum_reuse 0.1 \
       adc_bailout 0.005 max_sample 2 always_sample on normal on media off } }"
  in
  Alcotest.(check (list int)) "counts" [ 80; 3; 8 ] [ r.count; r.recursion_limit; r.nearest_count ];
  Scn.check_floats "floats" [ 0.7; 0.5; 0.2; 0.1; 0.01; 0.6; 0.01; 0.1; 0.005; 2. ]
    [ r.brightness; r.error_bound; r.gray_threshold; r.pretrace_start; r.pretrace_end; r.low_error_factor;
      r.minimum_reuse; r.maximum_reuse; r.adc_bailout; r.max_sample ];
  Alcotest.(check (list bool)) "switches" [ true; true; false ] [ r.always_sample; r.normal; r.media ];
  (* a scene before 3.7 keeps its ambient (POV-Ray's legacy rule) *)
  let r = settings ~raw:true "#version 3.6;\nglobal_settings { radiosity { } }" in
  Alcotest.(check bool) "3.6 keeps ambient" true r.keep_ambient;
  (* rad_def.inc's macro inside the block *)
  let r = settings "#include \"rad_def.inc\"\nglobal_settings { radiosity { Rad_Settings(Radiosity_Fast, on, off) } }" in
  Alcotest.(check bool) "rad_def.inc's normal switch" true r.normal

let errors () =
  Scn.check_message "global_settings { radiosity { recursion_limit 0 } }" "recursion_limit 0: it takes 1 to 20";
  Scn.check_message "global_settings { radiosity { nearest_count 30 } }" "nearest_count 30: it takes 1 to 20";
  Scn.check_message "global_settings { radiosity { error_bound -1 } }" "error_bound -1: it must be positive";
  Scn.check_message "global_settings { radiosity { importance 0.5 } }" "belongs in an object's radiosity block";
  Scn.check_message "sphere { 0, 1 radiosity { count 5 } }" "an object's radiosity block takes importance";
  Scn.check_message "global_settings { radiosity { brightness } }" "brightness needs a value"

(* a camera looking down at a plane under a uniform background, no light *)
let plane ?(version = "#version 3.7;") ?(extra = "") ?(rad = "") ?(finish = "diffuse 0.8 ambient 0.3") bg =
  Printf.sprintf
    "%s\nglobal_settings { assumed_gamma 1 radiosity { count 40 recursion_limit 1 %s } }\n\
     background { rgb %s }\ncamera { location <0, 2, -3> look_at 0 }\n\
     plane { y, 0 pigment { rgb 0.5 } finish { %s } }\n%s"
    version rad bg finish extra

let mid src = Whitted.pixel (Scn.compile ~raw:true src) ~width:8 ~height:6 4 3

(* a Lambertian plane under a uniform sky: every gather ray sees the sky,
   so the gathered light is the sky's, exactly: diffuse x pigment x sky *)
let sky_plane () =
  Scn.gray "0.8 x 0.5 x 1" 0.4 (mid (plane "1"));
  Scn.color "coloured sky" (0.4 *. 0.2, 0.4 *. 0.6, 0.4 *. 1.) (mid (plane "<0.2, 0.6, 1>"));
  Scn.gray "brightness 2.5" 1.0 (mid (plane ~rad:"brightness 2.5" "1"));
  (* gray_threshold 1: the grey value of the light, 0.297 r + 0.589 g + 0.114 b *)
  let g = Color.grey 0.2 0.6 1. in
  Scn.gray "gray_threshold 1" (0.4 *. g) (mid (plane ~rad:"gray_threshold 1" "<0.2, 0.6, 1>"));
  (* max_sample limits each ray's brightest channel *)
  Scn.gray "max_sample 0.5" 0.2 (mid (plane ~rad:"max_sample 0.5" "1"));
  (* from 3.7 ambient gives way to the radiosity; before, it is kept *)
  Scn.gray "3.6: ambient kept" (0.4 +. (0.3 *. 0.5)) (mid (plane ~version:"#version 3.6;" "1"));
  (* emission stays *)
  Scn.gray "emission" (0.4 +. 0.5 *. 0.25) (mid (plane ~finish:"diffuse 0.8 emission 0.25" "1"))

(* what gather rays see: a no_radiosity object is not there for them;
   an opaque black roof over the plane hides the sky from most rays *)
let hidden () =
  let roof flag = Printf.sprintf "disc { <0, 0.5, 0>, y, 100 %s pigment { rgb 0 } finish { ambient 0 diffuse 0 } }" flag in
  Scn.gray "a no_radiosity roof" 0.4 (mid (plane ~extra:(roof "no_radiosity no_image") "1"));
  let c = mid (plane ~extra:(roof "no_image") "1") in
  if c.r > 0.05 then Alcotest.failf "a roof seen by the gather: %.4f, expected nearly dark" c.r

(* media are seen by gather rays only with media on (POV-Ray, measured:
   a floor under a hollow shell of emitting media, no light, gathers 0,
   and 0.5 with media on) *)
let media_seen () =
  let shell media =
    Printf.sprintf
      "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 80 error_bound 0.5 recursion_limit 1 %s } }\n\
       camera { location <0, 1, -3> look_at <0, 0, 0> angle 10 }\n\
       plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
       difference { sphere { 0, 100 } sphere { 0, 99 } pigment { rgbt 1 } finish { ambient 0 diffuse 0 }\n\
      \  interior { media { emission 0.5 } } hollow no_shadow }"
      media
  in
  Scn.gray "media off" 0. (Scn.pixel ~raw:true (shell ""));
  Scn.gray "media on" 0.5 (Scn.pixel ~raw:true (shell "media on"))

(* the furnace: inside a closed sphere of emission e and diffuse d (white
   pigment), every gather ray sees the same radiance, so recursion n gives
   e (1 + b d + ... + (b d)^n) exactly *)
let furnace () =
  let inside ~limit ~b =
    Printf.sprintf
      "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 12 recursion_limit %d brightness %g } }\n\
       camera { location 0 look_at z }\nsphere { 0, 5 pigment { rgb 1 } finish { diffuse 0.5 emission 0.2 ambient 0.7 } }"
      limit b
  in
  let expect n b = 0.2 *. List.fold_left (fun acc k -> acc +. Float.pow (b *. 0.5) (float_of_int k)) 0. (List.init (n + 1) Fun.id) in
  List.iter
    (fun (n, b) ->
      let src = inside ~limit:n ~b in
      let s = Scn.compile ~raw:true src in
      (* through the cache, too *)
      Whitted.prepare s ~width:8 ~height:6;
      Scn.gray (Printf.sprintf "recursion %d brightness %g" n b) (expect n b) (Whitted.pixel s ~width:8 ~height:6 4 3))
    [ (1, 1.); (2, 1.); (3, 1.); (3, 1.5) ]

(* the gather's directions: unit, above the surface, cosine-weighted
   (mean cosine 2/3, mean squared cosine 1/2) *)
let directions =
  QCheck.Test.make ~count:200 ~name:"gather directions: unit, above, cosine-weighted"
    QCheck.(quad (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.) (pair (float_bound_exclusive 1.) (float_bound_exclusive 1.)))
    (fun (x, y, z, (r1, r2)) ->
      let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      QCheck.assume (l > 0.1);
      let n = Vec3.m () in
      Vec3.set n (x /. l) (y /. l) (z /. l);
      let d = Vec3.m () in
      let count = 400 in
      let s1 = ref 0. and s2 = ref 0. and ok = ref true in
      for i = 0 to count - 1 do
        Radiosity.direction_into n i count r1 r2 d;
        let len = Float.sqrt ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz)) in
        let c = (d.mx *. n.mx) +. (d.my *. n.my) +. (d.mz *. n.mz) in
        if Float.abs (len -. 1.) > 1e-9 || c < -1e-12 then ok := false;
        s1 := !s1 +. c;
        s2 := !s2 +. (c *. c)
      done;
      let m1 = !s1 /. float_of_int count and m2 = !s2 /. float_of_int count in
      !ok && Float.abs (m1 -. (2. /. 3.)) < 0.01 && Float.abs (m2 -. 0.5) < 0.01)

(* a lit box room with its cache: the same bytes on 1 and 2 domains, and
   the pretrace keeps records *)
let room =
  "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 20 recursion_limit 2 } }\n\
   camera { location <0, 1.5, -2.5> look_at <0, 1, 0> }\nlight_source { <0, 2.5, 0> rgb 1 }\n\
   box { <-1.5, 0, -3>, <1.5, 3, 1.5> hollow pigment { rgb 0.8 } }\n\
   sphere { <0.5, 0.4, 0>, 0.4 pigment { rgb <0.8, 0.2, 0.2> } }\n"

let domains () =
  let w = 40 and h = 30 in
  let s = Helpers.compile_string room in
  Whitted.prepare s ~width:w ~height:h;
  let r = match s.settings.radiosity with Some r -> r | None -> assert false in
  if Radiosity.records r.cache 0 < 10 then Alcotest.failf "only %d records" (Radiosity.records r.cache 0);
  let a = Render.image ~domains:1 ~width:w ~height:h (Whitted.pixel s ~width:w ~height:h) in
  let b = Render.image ~domains:2 ~width:w ~height:h (Whitted.pixel s ~width:w ~height:h) in
  Alcotest.(check bool) "1 and 2 domains: the same image" true (same_image a b);
  (* the pretrace again gives the same cache, so the same picture *)
  Whitted.prepare s ~width:w ~height:h;
  let c = Render.image ~domains:2 ~width:w ~height:h (Whitted.pixel s ~width:w ~height:h) in
  Alcotest.(check bool) "a second pretrace: the same image" true (same_image a c);
  let records () = List.init 3 (Radiosity.records r.cache) in
  let kept = records () in
  (* traced ahead on 2 domains, in batches small and large (the whole
     picture in one: its samples' records serve one another, and many
     are traced again): the same records, the same picture *)
  List.iter
    (fun batch ->
      Whitted.prepare ~par:(Render.pulled ~domains:2) ~batch s ~width:w ~height:h;
      Alcotest.(check (list int)) (Printf.sprintf "batches of %d: the records" batch) kept (records ());
      let d = Render.image ~domains:2 ~width:w ~height:h (Whitted.pixel s ~width:w ~height:h) in
      Alcotest.(check bool) (Printf.sprintf "batches of %d: the same image" batch) true (same_image a d))
    [ 1; 7; 128; w * h ];
  (* its progress: counts that grow, up to the whole (the passes' rays
     and every pixel), on one domain and on two *)
  List.iter
    (fun par ->
      let seen = ref [] in
      Whitted.prepare ?par ~progress:(fun ~done_ ~total -> seen := (done_, total) :: !seen) s ~width:w ~height:h;
      match !seen with
      | [] -> Alcotest.fail "no progress told"
      | (last, total) :: _ ->
          let dones = List.rev_map fst !seen in
          Alcotest.(check bool) "progress grows" true (List.sort_uniq compare dones = dones);
          Alcotest.(check int) "progress ends at the whole" total last;
          if total <= w * h then Alcotest.failf "a whole of %d for %d pixels and the passes" total (w * h))
    [ None; Some (Render.pulled ~domains:2) ];
  (* gathers three deep, 400 rays at the top: some samples traced ahead
     make over 8192 lookups and are abandoned (2 at this size), traced
     in turn: the same picture *)
  let deep = Helpers.compile_string (Str.global_replace (Str.regexp_string "count 20 recursion_limit 2") "count 400 recursion_limit 3" room) in
  let picture par =
    Whitted.prepare ?par deep ~width:8 ~height:6;
    Render.image ~domains:1 ~width:8 ~height:6 (Whitted.pixel deep ~width:8 ~height:6)
  in
  Alcotest.(check bool) "abandoned samples: the same image" true
    (same_image (picture None) (picture (Some (Render.pulled ~domains:2))));
  (* and the picture's pixels are the colours of the rays through their
     centres, traced when the pretrace reached them: near those traced
     with the whole cache (a pixel's colour in the wrong place would be
     far from it at the sphere's edges) *)
  let worst = ref 0. and sum = ref 0. in
  for y = 0 to h - 1 do
    for x = 0 to w - 1 do
      let q = Whitted.sample s ~width:w ~height:h (float_of_int x +. 0.5) (float_of_int y +. 0.5) in
      let d =
        Float.abs (Image.get_r a x y -. q.r) +. Float.abs (Image.get_g a x y -. q.g) +. Float.abs (Image.get_b a x y -. q.b)
      in
      worst := Float.max !worst d;
      sum := !sum +. d
    done
  done;
  Printf.printf "picture against the whole cache: worst %.4f, mean %.5f\n" !worst (!sum /. float_of_int (w * h));
  if !worst > 0.1 || !sum > 0.01 *. float_of_int (w * h) then
    Alcotest.failf "the picture against the whole cache: worst %.3f, mean %.4f" !worst (!sum /. float_of_int (w * h))

(* The picture's pass reads the cache allocating nothing: minor words a
   camera ray of the second of two one-domain renders after the pretrace
   (18.0 words, then 240.9 with the pretrace, before the lookup's floats
   went through the domain's sums instead of a closure, float refs and
   float arguments) *)
let allocation () =
  let s = Helpers.compile_string room in
  (* not the size Test_whitted.words_per_ray renders at (64x48), whose
     pixels the pretrace has traced: its rays look the cache up *)
  Whitted.prepare s ~width:48 ~height:36;
  let words = Test_whitted.words_per_ray s in
  if words > 0.1 then Alcotest.failf "%.2f minor words a camera ray" words

(* The cache keeps every record it is given, however many share a table
   slot and as it grows: a lookup over thousands of records (clustered
   and spread, reaches from 1e-3 to 10) weighs the same as the sum of
   lookups over each record alone. *)
let cache_keeps =
  QCheck.Test.make ~count:10 ~name:"cache: a lookup weighs every record as one cache each"
    (QCheck.make ~print:QCheck.Print.(pair int int) QCheck.Gen.(pair nat (int_range 300 1500)))
    (fun (seed, count) ->
      let st = Random.State.make [| seed |] in
      let f a = Random.State.float st a in
      let unit () =
        let x = f 2. -. 1. and y = f 2. -. 1. and z = f 2. -. 1. in
        let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
        if l < 1e-3 then (0., 1., 0.) else (x /. l, y /. l, z /. l)
      in
      (* normals near one another: a record serves only points whose
         normals are close to its own *)
      let up () =
        let x = 0.2 *. (f 2. -. 1.) and z = 0.2 *. (f 2. -. 1.) in
        let l = Float.sqrt ((x *. x) +. 1. +. (z *. z)) in
        (x /. l, 1. /. l, z /. l)
      in
      let record () =
        (* half in a small cluster, half spread out *)
        let spread = if Random.State.bool st then 0.05 else 20. in
        let nx, ny, nz = up () and tx, ty, tz = unit () in
        let hmd = Float.exp (f 9. -. 7.) in
        { Radiosity.px = f spread; py = f spread; pz = f spread; nx; ny; nz; ir = f 1.; ig = f 1.; ib = f 1.; hmd;
          near = hmd *. f 1.; tx; ty; tz }
      in
      let eb = 0.5 in
      let rs = List.init count (fun _ -> record ()) in
      let whole = Radiosity.new_cache () in
      List.iter (fun r -> Radiosity.add whole 0 r (r.Radiosity.hmd *. eb)) rs;
      let sm = Radiosity.sums () and out = Color.acc 0. in
      let ok = ref (Radiosity.records whole 0 = count) and served = ref 0 in
      for _ = 1 to 8 do
        let q = { Vec3.mx = f 0.05; my = f 0.05; mz = f 0.05 } in
        let nx, ny, nz = up () in
        let n = { Vec3.mx = nx; my = ny; mz = nz } in
        (* each record alone *)
        let ws = ref 0. and sr = ref 0. in
        List.iter
          (fun r ->
            let one = Radiosity.new_cache () in
            Radiosity.add one 0 r (r.Radiosity.hmd *. eb);
            sm.eb <- eb;
            Radiosity.lookup one 0 q n sm out;
            ws := !ws +. sm.ws;
            sr := !sr +. sm.sr)
          rs;
        if !ws > 0. then incr served;
        sm.eb <- eb;
        Radiosity.lookup whole 0 q n sm out;
        if Float.abs (sm.ws -. !ws) > 1e-9 *. (1. +. !ws) || Float.abs (sm.sr -. !sr) > 1e-9 *. (1. +. !sr) then
          ok := false
      done;
      (* most points are served by some record *)
      !ok && !served >= 4)

let tests =
  ( "radiosity",
    [
      Alcotest.test_case "settings: POV-Ray's defaults, every word" `Quick defaults;
      Alcotest.test_case "bad settings are errors" `Quick errors;
      Alcotest.test_case "a plane under a uniform sky: diffuse x pigment x sky" `Quick sky_plane;
      Alcotest.test_case "no_radiosity hides from gather rays" `Quick hidden;
      Alcotest.test_case "gather rays see object media only with media on" `Quick media_seen;
      Alcotest.test_case "furnace: e (1 + bd + ... + (bd)^n)" `Quick furnace;
      QCheck_alcotest.to_alcotest directions;
      QCheck_alcotest.to_alcotest cache_keeps;
      Alcotest.test_case "cache: 1 and 2 domains identical" `Quick domains;
      Alcotest.test_case "the picture's pass allocates nothing" `Quick allocation;
    ] )
