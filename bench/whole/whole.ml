(* Whole-render benchmarks, measured side by side in one run:

   1. domain scaling (the RTIOW final scene in mc mode, the snowman and
      the default scene in whitted mode, a 10^5-triangle mesh): each scene rendered with 1, 2, 4 (and more) domains,
      several runs, median; speed-up and parallel efficiency on the trace
      time that camlray reports, and on the whole wall time; beside them
      the machine's ceiling for two domains, from two one-domain renders
      run at once in the same rounds;
   2. camlray against POV-Ray 3.7 on the same whitted scenes, same size,
      anti-aliasing and thread count (+WT), POV-Ray's own trace time and
      the whole wall time;
   3. every scene of the cross-render harness at 640x480, one thread:
      camlray's trace time against POV-Ray's;
   4. the Ray Tracing in One Weekend final scene in mc mode at 400x225,
      32 spp, depth 50, one domain, as samples per second, beside the
      C++ reference (bench/rtiow-ref) timed in the same rounds.

   Writes bench/results/*.md and docs/scaling.svg. Usage:
     whole.exe [--quick] [--runs N] [--exe PATH] [--out DIR] *)

let runs = ref 5
let quick = ref false
let exe = ref "_build/install/default/bin/camlray"
let out_dir = ref "bench/results"
let svg_path = ref "docs/scaling.svg"

let median l =
  let a = Array.of_list l in
  Array.sort compare a;
  let n = Array.length a in
  if n = 0 then nan else if n mod 2 = 1 then a.(n / 2) else (a.((n / 2) - 1) +. a.(n / 2)) /. 2.

let read_file f = In_channel.with_open_bin f In_channel.input_all

(* Run a command, return (wall seconds, stderr text). *)
let timed cmd =
  let err = Filename.temp_file "bench" ".err" in
  let t0 = Unix.gettimeofday () in
  let code = Sys.command (cmd ^ " 2>" ^ Filename.quote err ^ " >/dev/null") in
  let dt = Unix.gettimeofday () -. t0 in
  let text = read_file err in
  Sys.remove err;
  if code <> 0 then failwith (Printf.sprintf "command failed (%d): %s\n%s" code cmd text);
  (dt, text)

(* "render 1.23 s" in camlray's summary line (the first [key] followed by
   a number: a warning before it may use the word too) *)
let find_float_after key text =
  let n = String.length key in
  let rec go i =
    if i + n > String.length text then None
    else if String.sub text i n = key then
      let j = ref (i + n) in
      while !j < String.length text && (text.[!j] = ' ' || text.[!j] = ':') do incr j done;
      let k = ref !j in
      while !k < String.length text && (match text.[!k] with '0' .. '9' | '.' -> true | _ -> false) do incr k done;
      match float_of_string_opt (String.sub text !j (!k - !j)) with
      | Some x -> Some x
      | None -> go (i + 1)
    else go (i + 1)
  in
  go 0

type scene = { name : string; file : string; args : string list }

let camlray s ~domains ~w ~h extra =
  let out = Filename.temp_file "bench" ".png" in
  let cmd =
    String.concat " "
      (List.map Filename.quote
         ([ !exe; "render"; s.file; "-W"; string_of_int w; "-H"; string_of_int h; "--domains";
            string_of_int domains; "-o"; out ] @ s.args @ extra))
  in
  let wall, text = timed cmd in
  Sys.remove out;
  match find_float_after "render" text with
  | Some trace -> (wall, trace)
  | None -> failwith ("no render time in: " ^ text)

(* Two one-domain renders at once, in two processes: the trace times
   they report, averaged. What the machine gives two independent copies
   of the same work: 2 t1 / t_pair is the speed-up two domains would reach
   if camlray's parallel loop cost nothing (a shared cache, memory or a
   busy neighbour on the host slow both copies alike). *)
let camlray_pair s ~w ~h =
  let one () =
    let out = Filename.temp_file "bench" ".png" and err = Filename.temp_file "bench" ".err" in
    let cmd =
      String.concat " "
        (List.map Filename.quote
           ([ !exe; "render"; s.file; "-W"; string_of_int w; "-H"; string_of_int h; "--domains"; "1"; "-o"; out ] @ s.args))
    in
    (cmd ^ " 2>" ^ Filename.quote err ^ " >/dev/null", out, err)
  in
  let c1, o1, e1 = one () and c2, o2, e2 = one () in
  ignore (Sys.command (Printf.sprintf "( %s ) & ( %s ); wait" c1 c2));
  let time err =
    let text = read_file err in
    (try Sys.remove err with Sys_error _ -> ());
    match find_float_after "render" text with Some t -> t | None -> failwith ("no render time in: " ^ text)
  in
  let t1 = time e1 and t2 = time e2 in
  List.iter (fun f -> try Sys.remove f with Sys_error _ -> ()) [ o1; o2 ];
  (t1 +. t2) /. 2.

let povray_available () = Sys.command "command -v povray >/dev/null 2>&1" = 0

let povray s ~threads ~w ~h ~aa =
  let out = Filename.temp_file "bench" ".png" in
  let cmd =
    Printf.sprintf "povray +I%s +O%s +W%d +H%d -D +FN +WT%d +L%s %s" (Filename.quote s.file)
      (Filename.quote out) w h threads (Filename.quote (Filename.dirname s.file))
      (if aa then "+A0.3 +R3 -J" else "-A")
  in
  let wall, text = timed cmd in
  Sys.remove out;
  (* POV-Ray prints "Trace Time:       0 hours  0 minutes  0 seconds (0.369 seconds)" *)
  let trace =
    match String.split_on_char '\n' text |> List.find_opt (fun l -> String.length l > 10 && String.sub (String.trim l) 0 (min 10 (String.length (String.trim l))) = "Trace Time") with
    | Some l -> (
        match String.index_opt l '(' with
        | Some i -> find_float_after "(" (String.sub l i (String.length l - i))
        | None -> None)
    | None -> None
  in
  (wall, Option.value trace ~default:nan)

let rep n f = List.init n (fun _ -> f ())

(* The C++ reference of the third benchmark (bench/rtiow-ref/rtiow.cc, the
   design of Ray Tracing in One Weekend: one thread, no BVH), built with
   g++ -O3 when there is a g++; None otherwise. *)
let reference_exe () =
  let src = "bench/rtiow-ref/rtiow.cc" in
  if not (Sys.file_exists src && Sys.command "command -v g++ >/dev/null 2>&1" = 0) then begin
    prerr_endline "whole: no g++, so the C++ reference is not timed (apt-get install g++)";
    None
  end
  else
    let exe = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "camlray-rtiow-%d" (Unix.getpid ())) in
    if Sys.command (Printf.sprintf "g++ -O3 -o %s %s" (Filename.quote exe) (Filename.quote src)) <> 0 then begin
      prerr_endline "whole: the C++ reference did not build; not timed";
      None
    end
    else begin
      at_exit (fun () -> try Sys.remove exe with Sys_error _ -> ());
      Some exe
    end

(* (spheres, render seconds) as the reference reports them on stderr *)
let run_reference exe ~w ~h ~spp =
  let _, text = timed (Printf.sprintf "%s %d %d %d 50" (Filename.quote exe) w h spp) in
  match (find_float_after "spheres" text, find_float_after "seconds" text) with
  | Some n, Some t -> (int_of_float n, t)
  | _ -> failwith ("the C++ reference printed no time: " ^ text)

(* Runs interleaved: run 1 of every domain count, then run 2, ..., so that
   a slow spell of this shared machine falls on all counts alike; every
   other round takes the counts in reverse order, so that a machine
   slowing down or speeding up through a round favours no count. Beside
   the ratio of the medians, the paired speed-up: the median over rounds
   of each round's own ratio (runs seconds apart, where the medians' runs
   may be minutes apart on a machine whose speed changes by 2x to 4x
   within minutes). For a
   whitted scene POV-Ray's own speed-up from 1 to 2 threads on the same
   scene and size is measured in the same rounds: what this machine gives
   a C++ renderer. *)
let scaling_table scenes domain_counts =
  let buf = Buffer.create 1024 in
  Buffer.add_string buf
    "| scene | domains | trace s (median) | speed-up (of medians) | paired speed-up (median of rounds) | efficiency | wall s | wall speed-up | best trace s | best speed-up | machine ceiling (2 one-domain runs at once, paired) | paired speed-up / ceiling | POV-Ray speed-up (same rounds) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  let curves =
    List.map
      (fun (s, w, h, pov) ->
        let pov = pov && povray_available () in
        let rounds =
          List.init !runs (fun i ->
              let counts = if i mod 2 = 0 then domain_counts else List.rev domain_counts in
              let cam = List.map (fun d -> (d, camlray s ~domains:d ~w ~h [])) counts in
              let pair = camlray_pair s ~w ~h in
              let p =
                if pov then List.map (fun t -> (t, snd (povray s ~threads:t ~w ~h ~aa:false))) [ 1; 2 ] else []
              in
              (cam, pair, p))
        in
        let results =
          List.map
            (fun d ->
              let samples = List.map (fun (cam, _, _) -> List.assoc d cam) rounds in
              (* best: the fastest run, what the machine gives when nothing
                 else runs on it (these machines are shared) *)
              let best = List.fold_left (fun m (_, t) -> Float.min m t) infinity samples in
              (d, median (List.map snd samples), median (List.map fst samples), best))
            domain_counts
        in
        let pov_speedup t =
          if not pov then "-"
          else if t = 1 then "1.00x"
          else if t = 2 then
            Printf.sprintf "%.2fx" (median (List.map (fun (_, _, p) -> List.assoc 1 p /. List.assoc 2 p) rounds))
          else "-"
        in
        let _, t1, w1, b1 = List.hd results in
        let trace (cam, _, _) d = snd (List.assoc d cam) in
        let paired d = median (List.map (fun r -> trace r 1 /. trace r d) rounds) in
        let ceiling = median (List.map (fun ((_, pair, _) as r) -> 2. *. trace r 1 /. pair) rounds) in
        List.iter
          (fun (d, t, wall, best) ->
            let ceil =
              if d = 2 then Printf.sprintf "%.2fx | %.0f%%" ceiling (100. *. paired d /. ceiling) else "- | -"
            in
            Buffer.add_string buf
              (Printf.sprintf "| %s | %d | %.3f | %.2fx | %.2fx | %.0f%% | %.3f | %.2fx | %.3f | %.2fx | %s | %s |\n" s.name d t
                 (t1 /. t) (paired d) (100. *. t1 /. t /. float d) wall (w1 /. wall) best (b1 /. best) ceil (pov_speedup d)))
          results;
        (s.name, List.map (fun (d, t, _, _) -> (d, t1 /. t)) results))
      scenes
  in
  (Buffer.contents buf, curves)

let svg curves max_d =
  let w = 480. and h = 320. and m = 50. in
  let sx d = m +. ((float d -. 1.) /. (float max_d -. 1.) *. (w -. (2. *. m))) in
  let sy v = h -. m -. ((v -. 0.) /. float max_d *. (h -. (2. *. m))) in
  let colors = [| "#d62728"; "#1f77b4"; "#2ca02c"; "#9467bd" |] in
  let b = Buffer.create 2048 in
  Buffer.add_string b
    (Printf.sprintf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n" w h);
  Buffer.add_string b
    (Printf.sprintf "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n<text x=\"%.1f\" y=\"%.1f\" fill=\"#999\">ideal</text>\n"
       (sx 1) (sy 1.) (sx max_d) (sy (float max_d)) (sx max_d -. 30.) (sy (float max_d) -. 6.));
  Buffer.add_string b
    (Printf.sprintf "<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"black\"/>\n<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"black\"/>\n"
       m (h -. m) (w -. m) (h -. m) m (h -. m) m m);
  for d = 1 to max_d do
    Buffer.add_string b (Printf.sprintf "<text x=\"%.1f\" y=\"%.0f\" text-anchor=\"middle\">%d</text>\n" (sx d) (h -. m +. 16.) d)
  done;
  for v = 0 to max_d do
    Buffer.add_string b (Printf.sprintf "<text x=\"%.0f\" y=\"%.1f\" text-anchor=\"end\">%d</text>\n" (m -. 6.) (sy (float v) +. 4.) v)
  done;
  Buffer.add_string b (Printf.sprintf "<text x=\"%.0f\" y=\"%.0f\" text-anchor=\"middle\">domains</text>\n" (w /. 2.) (h -. 12.));
  Buffer.add_string b (Printf.sprintf "<text x=\"14\" y=\"%.0f\" transform=\"rotate(-90 14 %.0f)\" text-anchor=\"middle\">speed-up (trace time)</text>\n" (h /. 2.) (h /. 2.));
  List.iteri
    (fun i (name, pts) ->
      let c = colors.(i mod Array.length colors) in
      let path = String.concat " " (List.map (fun (d, v) -> Printf.sprintf "%.1f,%.1f" (sx d) (sy v)) pts) in
      Buffer.add_string b (Printf.sprintf "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" points=\"%s\"/>\n" c path);
      List.iter (fun (d, v) -> Buffer.add_string b (Printf.sprintf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n" (sx d) (sy v) c)) pts;
      Buffer.add_string b (Printf.sprintf "<text x=\"%.0f\" y=\"%.0f\" fill=\"%s\">%s</text>\n" (m +. 10.) (m +. 14. +. (16. *. float i)) c name))
    curves;
  Buffer.add_string b "</svg>\n";
  Buffer.contents b

let pov_table scenes =
  let b = Buffer.create 1024 in
  Buffer.add_string b
    "| scene | size | AA | threads | camlray trace s | POV-Ray trace s | trace ratio | camlray wall s | POV-Ray wall s | wall ratio |\n|---|---|---|---|---|---|---|---|---|---|\n";
  List.iter
    (fun (s, w, h, aa) ->
      List.iter
        (fun threads ->
          (* interleaved, as in the scaling table *)
          let rounds =
            rep !runs (fun () ->
                let c = camlray s ~domains:threads ~w ~h (if aa then [ "--aa"; "0.3" ] else []) in
                (c, povray s ~threads ~w ~h ~aa))
          in
          let c = List.map fst rounds and p = List.map snd rounds in
          let ct = median (List.map snd c) and cw = median (List.map fst c) in
          let pt = median (List.map snd p) and pw = median (List.map fst p) in
          Buffer.add_string b
            (Printf.sprintf "| %s | %dx%d | %s | %d | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f |\n" s.name w h
               (if aa then "+A0.3" else "off") threads ct pt (ct /. pt) cw pw (cw /. pw)))
        [ 1; 2 ])
    scenes;
  Buffer.contents b

(* The scenes of the cross-render harness (the folders make test
   compares with POV-Ray at 160x120, and the default scene), one thread
   each, without anti-aliasing: camlray's trace time against POV-Ray's own,
   [rounds] alternated runs (POV-Ray first in every other round), the
   ratio of the medians; a scene whose ratio is then within 10% of 1
   gets rounds up to [close_rounds], so that the host's noise decides
   fewer of the scenes near the line (on a noisy host, two runs of 2
   rounds each put 20 and 8 scenes above 1.0, one scene in both). A
   scene POV-Ray reports no trace time for is listed without a ratio. *)
let harness_table files ~w ~h ~rounds ~close_rounds =
  let b = Buffer.create 4096 in
  Buffer.add_string b
    (Printf.sprintf
       "| scene | camlray trace s | POV-Ray trace s | trace ratio | rounds |\n|---|---|---|---|---|\n");
  let ratios =
    List.filter_map
      (fun file ->
        let sc = { name = Filename.remove_extension (Filename.basename file); file; args = [] } in
        let round i =
          let pov () = snd (povray sc ~threads:1 ~w ~h ~aa:false) in
          let cam () = snd (camlray sc ~domains:1 ~w ~h []) in
          if i mod 2 = 0 then
            let c = cam () in
            (c, pov ())
          else
            let p = pov () in
            (cam (), p)
        in
        let first = List.init rounds round in
        let ratio runs = median (List.map fst runs) /. median (List.map snd runs) in
        let runs =
          let r = ratio first in
          if r >= 0.9 && r <= 1.1 && close_rounds > rounds then
            first @ List.init (close_rounds - rounds) (fun i -> round (rounds + i))
          else first
        in
        let c = median (List.map fst runs) and p = median (List.map snd runs) in
        if Float.is_nan p || p <= 0. then begin
          Buffer.add_string b (Printf.sprintf "| %s | %.3f | - | - | %d |\n" sc.name c (List.length runs));
          None
        end
        else begin
          Buffer.add_string b (Printf.sprintf "| %s | %.3f | %.3f | %.2f | %d |\n" sc.name c p (c /. p) (List.length runs));
          Some (sc.name, c /. p)
        end)
      files
  in
  let n = List.length ratios in
  if n > 0 then begin
    let geo = Float.exp (List.fold_left (fun a (_, r) -> a +. Float.log r) 0. ratios /. float n) in
    let above = List.filter (fun (_, r) -> r > 1.) ratios in
    let sorted = List.sort compare (List.map snd ratios) in
    Buffer.add_string b
      (Printf.sprintf
         "\n%d scenes at %dx%d, one thread, no anti-aliasing: trace ratio at most 1.0 on %d; geometric mean %.2f, lowest %.2f, highest %.2f%s\n"
         n w h (n - List.length above) geo (List.hd sorted) (List.nth sorted (n - 1))
         (if above = [] then ""
          else
            "; above 1.0: "
            ^ String.concat ", " (List.map (fun (name, r) -> Printf.sprintf "%s (%.2f)" name r) above)))
  end;
  Buffer.contents b

let write path text =
  (try Sys.mkdir (Filename.dirname path) 0o755 with Sys_error _ -> ());
  Out_channel.with_open_bin path (fun oc -> output_string oc text);
  Printf.printf "wrote %s\n" path

(* the harness table (see [harness_table]) into harness.md *)
let run_harness () =
  let files =
    "scenes/default.scn"
    :: List.concat_map
         (fun d ->
           if Sys.file_exists d && Sys.is_directory d then
             Sys.readdir d |> Array.to_list
             |> List.filter (fun f -> Filename.check_suffix f ".pov" || Filename.check_suffix f ".scn")
             |> List.sort compare
             |> List.map (Filename.concat d)
           else [])
         [ "scenes/seeds"; "scenes/whitted"; "scenes/whitted-extra" ]
  in
  let files = List.filter Sys.file_exists files in
  let files = if !quick then List.filteri (fun i _ -> i < 3) files else files in
  let w, h = if !quick then (32, 24) else (640, 480) in
  let t = harness_table files ~w ~h ~rounds:(if !quick then 1 else 2) ~close_rounds:(if !quick then 1 else 6) in
  print_string t;
  write (Filename.concat !out_dir "harness.md") t

let harness_only = ref false

let () =
  Arg.parse
    [ ("--quick", Arg.Set quick, " tiny sizes, one run (a smoke test)");
      ("--runs", Arg.Set_int runs, "N runs per measurement (median)");
      ("--exe", Arg.Set_string exe, "PATH the camlray executable");
      ("--out", Arg.Set_string out_dir, "DIR where the tables go");
      ("--svg", Arg.Set_string svg_path, "PATH the scaling plot");
      ("--harness-only", Arg.Set harness_only, " only the harness scenes against POV-Ray (harness.md)") ]
    (fun _ -> ()) "whole.exe [options]";
  if !quick then runs := 1;
  if !harness_only then begin
    if povray_available () then run_harness () else prerr_endline "whole: povray is not installed";
    exit 0
  end;
  let sz w h = if !quick then (max 8 (w / 20), max 6 (h / 20)) else (w, h) in
  let s name file args = { name; file; args } in
  (* the seed scenes, or their bench/scenes variants while camlray lacks a
     feature they use (sky_sphere, checker) *)
  let renders file = Sys.file_exists file && (try ignore (camlray (s "" file []) ~domains:1 ~w:8 ~h:6 []); true with Failure _ -> false) in
  let pick seed variant = if renders seed || not (Sys.file_exists variant) then seed else variant in
  let rtiow_file = pick "scenes/seeds/howard-final.scn" "bench/scenes/rtiow-final-bg.scn" in
  let snowman_file = pick "scenes/seeds/diagrams-snowman.scn" "bench/scenes/snowman-plain.scn" in
  let variant f = if String.length f > 6 && String.sub f 0 6 = "bench/" then " [bench variant]" else "" in
  let rtiow = s ("RTIOW final (mc, 16 spp)" ^ variant rtiow_file) rtiow_file [ "--mode"; "mc"; "--spp"; "16" ] in
  let snowman = s ("snowman (whitted)" ^ variant snowman_file) snowman_file [] in
  let default = s "default (whitted)" "scenes/default.scn" [] in
  let mesh = s "10^5-triangle mesh (whitted)" "bench/scenes/mesh-100k.scn" [] in
  let available sc = Sys.file_exists sc.file in
  let ncores = Domain.recommended_domain_count () in
  let domain_counts = List.sort_uniq compare [ 1; 2; ncores; 2 * ncores ] in
  let scaling_scenes =
    List.filter (fun (sc, _, _, _) -> available sc)
      [ (let w, h = sz 400 225 in (rtiow, w, h, false)); (let w, h = sz 1600 1200 in (snowman, w, h, true));
        (let w, h = sz 1600 1200 in (default, w, h, true)); (let w, h = sz 1600 1200 in (mesh, w, h, true)) ]
  in
  let working =
    List.filter
      (fun (sc, _, _, _) ->
        try ignore (camlray sc ~domains:1 ~w:8 ~h:6 []); true
        with Failure e -> Printf.eprintf "skipping %s: %s\n" sc.name e; false)
      scaling_scenes
  in
  let table, curves = scaling_table working domain_counts in
  print_string table;
  write (Filename.concat !out_dir "scaling.md") table;
  if not !quick then write !svg_path (svg curves (List.fold_left max 1 domain_counts));
  if povray_available () then begin
    let pov_scenes =
      List.filter (fun (sc, _, _, _) -> List.exists (fun (x, _, _, _) -> x == sc) working)
        [ (let w, h = sz 800 600 in (snowman, w, h, false)); (let w, h = sz 800 600 in (default, w, h, false));
          (* trace-only comparison on a larger image (POV-Ray's 0.7 s start-up
             weighs less) *)
          (let w, h = sz 1600 1200 in (snowman, w, h, false)); (let w, h = sz 1600 1200 in (default, w, h, false));
          (let w, h = sz 1600 1200 in (mesh, w, h, false)) ]
    in
    let t = pov_table pov_scenes in
    print_string t;
    write (Filename.concat !out_dir "povray.md") t;
    run_harness ()
  end;
  if List.exists (fun (sc, _, _, _) -> sc == rtiow) working then begin
    let w, h = sz 400 225 in
    let spp = if !quick then 2 else 32 in
    let one = { rtiow with args = [ "--mode"; "mc"; "--spp"; string_of_int spp; "--depth"; "50" ] } in
    let reference = reference_exe () in
    (* interleaved with the C++ reference, which takes some 15 s a run on
       a quiet machine: three rounds at most *)
    let rounds = if reference = None then !runs else min 3 !runs in
    let r =
      rep rounds (fun () ->
          let c = camlray one ~domains:1 ~w ~h [] in
          (c, Option.map (fun exe -> run_reference exe ~w ~h ~spp) reference))
    in
    let t = median (List.map (fun (c, _) -> snd c) r) in
    let sps = float (w * h * spp) /. t in
    let ref_cell, ratio_cell =
      match List.filter_map snd r with
      | [] -> ("-", "-")
      | l ->
          let rs = float (w * h * spp) /. median (List.map snd l) in
          (Printf.sprintf "%.0f (%d spheres)" rs (fst (List.hd l)), Printf.sprintf "**%.2fx**" (sps /. rs))
    in
    let text =
      Printf.sprintf
        "| render | camlray samples/s (1 domain) | C++ reference, same run | ratio | C++ reference (perf-anchors.md) | ratio |\n\
         |---|---|---|---|---|---|\n\
         | RTIOW final%s %dx%d, %d spp, depth 50 | %.0f | %s | %s | 204000 | %.2fx |\n"
        (variant rtiow_file) w h spp sps ref_cell ratio_cell (sps /. 204000.)
    in
    print_string text;
    write (Filename.concat !out_dir "rtiow.md") text
  end
