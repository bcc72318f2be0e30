(* POV-Ray 3.7's ripples and waves (their wave sources and frequencies),
   its normals with formulas of their own (bumps, dents, wrinkles,
   ripples, waves, quilted), facets and iridescence's turbulence, against
   data POV-Ray wrote: the files in waves_pov/ were written by POV-Ray
   3.7.0 running the .pov files beside them (see each file's head). *)
open Camlray

let pov_dir = Helpers.data_dir "waves_pov"

let read_rows = Helpers.read_rows pov_dir

let single = Floats.single

(* the patterns of waves.pov, as its pigment functions write them *)
let pov_patterns =
  Alcotest.test_case "ripples and waves: POV-Ray's pattern values at 300 points" `Quick (fun () ->
      let rows = read_rows "patterns.txt" in
      if List.length rows <> 300 then Alcotest.failf "%d rows" (List.length rows);
      Pattern.set_number_of_waves 10;
      let pat ?(frequency = 1.) ?(phase = 0.) ?wave kind =
        { (Pattern.make kind) with frequency = single frequency; phase = single phase; wave }
      in
      let pats =
        [
          ("ripples", pat Pattern.Ripples);
          ("waves", pat Pattern.Waves);
          ("ripples frequency 2.7 phase 0.3", pat ~frequency:2.7 ~phase:0.3 Pattern.Ripples);
          ("waves frequency 0.6 phase -0.45", pat ~frequency:0.6 ~phase:(-0.45) Pattern.Waves);
          ("ripples sine_wave", pat ~wave:Pattern.Sine Pattern.Ripples);
          ("waves frequency -1.3", pat ~frequency:(-1.3) Pattern.Waves);
        ]
      in
      List.iter
        (function
          | x :: y :: z :: vs ->
              List.iter2
                (fun (name, (t : Pattern.t)) v ->
                  let got = Pattern.value t (Vec3.make x y z) in
                  (* POV-Ray prints 17 decimals; the sine wave's shaping
                     (Pattern's, 0.5 + 0.5 sin 2 pi v, where POV-Ray takes
                     (1 + cycloidal v) / 2) differs in the last bits *)
                  let eps = if t.wave = None then 2e-16 else 1e-15 in
                  if Float.abs (got -. v) > eps then
                    Alcotest.failf "%s at (%.17g, %.17g, %.17g): %.17g, POV-Ray %.17g" name x y z got v)
                pats vs
          | _ -> Alcotest.fail "bad row")
        rows)

(* A 16-bit binary PPM as POV-Ray writes it (comment lines in the
   header): width, height, and the channels as fractions of 65535 *)
let read_ppm path =
  let d = In_channel.with_open_bin path In_channel.input_all in
  let pos = ref 0 in
  let rec token () =
    while !pos < String.length d && (d.[!pos] = ' ' || d.[!pos] = '\n' || d.[!pos] = '\r' || d.[!pos] = '\t') do
      incr pos
    done;
    if d.[!pos] = '#' then begin
      while d.[!pos] <> '\n' do
        incr pos
      done;
      token ()
    end
    else begin
      let s = !pos in
      while not (d.[!pos] = ' ' || d.[!pos] = '\n' || d.[!pos] = '\r' || d.[!pos] = '\t') do
        incr pos
      done;
      String.sub d s (!pos - s)
    end
  in
  let magic = token () in
  let w = int_of_string (token ()) in
  let h = int_of_string (token ()) in
  let m = int_of_string (token ()) in
  if magic <> "P6" || m <> 65535 then Alcotest.failf "%s: not a 16-bit P6 PPM" path;
  let start = !pos + 1 in
  let v x y c =
    let k = start + (6 * ((y * w) + x)) + (2 * c) in
    float_of_int ((Char.code d.[k] lsl 8) lor Char.code d.[k + 1]) /. 65535.
  in
  (w, h, v)

(* camlray's render of a .pov of waves_pov/ against POV-Ray's picture of
   it: every channel of every pixel within [eps] (16-bit steps) *)
let same_picture ?(eps = 0.75) name =
  let scene = In_channel.with_open_bin (Filename.concat pov_dir (name ^ ".pov")) In_channel.input_all in
  let w, h, pov = read_ppm (Filename.concat pov_dir (name ^ ".ppm")) in
  let img = Helpers.render_whitted ~width:w ~height:h scene in
  let worst = ref 0. and at = ref (0, 0, 0) in
  for y = 0 to h - 1 do
    for x = 0 to w - 1 do
      let r, g, b = Helpers.pixel img x y in
      List.iteri
        (fun c ours ->
          let d = Float.abs (ours -. pov x y c) *. 65535. in
          if d > !worst then begin
            worst := d;
            at := (x, y, c)
          end)
        [ r; g; b ]
    done
  done;
  let x, y, c = !at in
  if Sys.getenv_opt "WAVES_VERBOSE" <> None then Printf.printf "%s: %.2f steps at most\n%!" name !worst;
  if !worst > eps then
    Alcotest.failf "%s: pixel (%d, %d) channel %d is %.1f steps of 65535 from POV-Ray's (%.6f against %.6f)" name x y c
      !worst
      (let r, g, b = Helpers.pixel img x y in
       List.nth [ r; g; b ] c)
      (pov x y c)

(* The normal probes of make-normals.sh: a plane under the normal, lit
   by a red light from -x, a green one from -y and a blue one head-on:
   the normal patterns' own formulas, and the generic slope of bozo,
   spotted (with a slope_map), granite, bumps under a normal_map, and
   facets (also with coords) over POV-Ray's pattern values and crackle's
   points *)
let probes =
  [
    "bumps"; "bumps-slope"; "bumps-warp"; "dents"; "dents-gen1"; "dents-gen3"; "wrinkles"; "ripples"; "ripples-3";
    "waves"; "waves-25"; "quilted"; "leopard-hole"; "gradient-warp"; "ripples-map"; "bozo"; "spotted"; "granite";
    "bumps-map"; "facets"; "facets-coords";
  ]

let pov_normals =
  Alcotest.test_case "normals: POV-Ray's 16-bit pictures of 21 probes, pixel for pixel" `Quick (fun () ->
      List.iter (fun p -> same_picture ("n-" ^ p)) probes)

(* The scene probes of make-renders.sh: ripples and waves pigments (the
   scene's number_of_waves) and iridescence's turbulence (the scene's
   noise generator), a plane lit head-on *)
let pov_scenes =
  Alcotest.test_case "ripples, waves, irid, caustics: POV-Ray's 16-bit pictures of 11 probes, pixel for pixel" `Quick (fun () ->
      List.iter
        (fun p -> same_picture ("s-" ^ p))
        [ "ripples"; "ripples-5"; "waves"; "waves-1"; "irid"; "irid-gen1"; "irid-gen3"; "irid-bumps"; "irid-reflect"; "irid-tir"; "caustics" ])

(* number_of_waves: a global_settings item (POV-Ray 3.7 rejects it in a
   pattern); below 1 it is 1, with POV-Ray's warning; the compiler sets
   the scene's *)
let number_of_waves () =
  Scn.check_message "sphere { 0, 1 pigment { ripples number_of_waves 3 } }"
    "number_of_waves is a global_settings item";
  Scn.check_message "sphere { 0, 1 normal { waves 0.5 number_of_waves 3 } }"
    "number_of_waves is a global_settings item";
  let warned =
    Camlray_lang.Diag.collect_warnings (fun () ->
        ignore (Scn.compile "global_settings { number_of_waves 0 }\nsphere { 0, 1 pigment { ripples } }"))
  in
  if not (Scn.contains (snd warned) "number_of_waves must be greater than 0") then
    Alcotest.failf "no warning: %S" (snd warned);
  Alcotest.(check int) "0 taken as 1" 1 (Pattern.waves ()).count;
  ignore (Scn.compile "global_settings { number_of_waves 7.9 }");
  Alcotest.(check int) "7.9 taken as 7" 7 (Pattern.waves ()).count;
  ignore (Scn.compile "sphere { 0, 1 }");
  Alcotest.(check int) "10 by default" 10 (Pattern.waves ()).count;
  (* the sources are a prefix: the first 7 of 25 are the 7 *)
  let a = Pattern.make_waves 7 and b = Pattern.make_waves 25 in
  for i = 0 to 20 do
    if Float.Array.get a.src i <> Float.Array.get b.src i then Alcotest.failf "source coordinate %d" i
  done;
  for i = 0 to 6 do
    if Float.Array.get a.freq i <> Float.Array.get b.freq i then Alcotest.failf "frequency %d" i;
    let f = Float.Array.get a.freq i in
    if not (f >= 0.01 && f <= 1.01) then Alcotest.failf "frequency %d: %g" i f
  done

let tests =
  ( "waves",
    [
      pov_patterns;
      pov_normals;
      pov_scenes;
      Alcotest.test_case "number_of_waves: where, how many, errors" `Quick number_of_waves;
    ] )
