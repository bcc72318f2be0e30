open Camlray
open Camlray_lang

type mode = Whitted | Monte_carlo

type render_opts = {
  scene : string option;
  output : string option;
  width : int;
  height : int;
  mode : mode;
  spp : int;
  depth : int option;
  domains : int option;
  seed : int;
  quiet : bool;
  include_dirs : string list;
  aa : float option;  (** anti-aliasing threshold (POV-Ray's +A) *)
  aa_depth : int;  (** POV-Ray's +R *)
}

exception Fail of string
(* a one-line error (exit 1) *)

let fail fmt = Printf.ksprintf (fun s -> raise (Fail s)) fmt

let check_range name v lo hi =
  if v < lo || v > hi then fail "%s must be between %d and %d, got %d" name lo hi v

let max_pixels = 1 lsl 27 (* 134M pixels: 3.2 GB of float frame buffer *)

let validate o =
  check_range "width (-W)" o.width 1 65535;
  check_range "height (-H)" o.height 1 65535;
  if o.width * o.height > max_pixels then
    fail "image of %d x %d = %d pixels is larger than the limit of %d pixels" o.width o.height
      (o.width * o.height) max_pixels;
  check_range "--spp" o.spp 1 1_000_000;
  Option.iter (fun d -> check_range "--depth" d 1 256) o.depth;
  Option.iter (fun d -> check_range "--domains" d 1 256) o.domains;
  check_range "--aa-depth" o.aa_depth 1 9;
  Option.iter
    (fun t -> if not (t >= 0. && t <= 3.) then fail "--aa must be between 0 and 3, got %g" t)
    o.aa

let load ~options scene =
  match scene with
  | None ->
      let name = "default.scn" in
      Result.map (fun s -> (s, [])) (Parse.string ~options ~name Default_scene.text)
  | Some path ->
      if not (Sys.file_exists path) then fail "cannot read scene %s: no such file" path;
      if Sys.is_directory path then fail "cannot read scene %s: it is a folder" path;
      Parse.file ~options path

let compile ~options scene =
  match load ~options scene with
  | Error d -> Error d
  | Ok (sdl, files) -> Result.map (fun s -> (s, files)) (Compile.scene sdl)

let output_path o =
  match o.output with
  | Some p -> p
  | None ->
      let base = match o.scene with Some s -> Filename.basename s | None -> "default.scn" in
      Filename.remove_extension base ^ ".png"

let same_file a b =
  try
    let sa = Unix.stat a and sb = Unix.stat b in
    sa.st_dev = sb.st_dev && sa.st_ino = sb.st_ino
  with Unix.Unix_error _ -> false

let progress_bar ~start ~done_ ~total =
  let frac = float_of_int done_ /. float_of_int total in
  let elapsed = Unix.gettimeofday () -. start in
  let eta = if frac > 0. then elapsed *. (1. -. frac) /. frac else 0. in
  let width = 30 in
  let filled = int_of_float (frac *. float_of_int width) in
  Printf.eprintf "\r[%s%s] %3.0f%%  ETA %5.1fs " (String.make filled '#')
    (String.make (width - filled) '.') (100. *. frac) eta;
  flush stderr

let cancelled = Atomic.make false

let with_signals f =
  let handle = Sys.Signal_handle (fun _ -> Atomic.set cancelled true) in
  let old_int = Sys.signal Sys.sigint handle in
  let old_term = Sys.signal Sys.sigterm handle in
  Fun.protect f ~finally:(fun () ->
      Sys.set_signal Sys.sigint old_int;
      Sys.set_signal Sys.sigterm old_term)

let write_image path (scene : Scene.t) img =
  match String.lowercase_ascii (Filename.extension path) with
  | ".pfm" -> Image.write_pfm path img
  | ".ppm" -> Image.write_ppm path (Image.to_rgb8 scene.settings.encoding img)
  | _ -> Image.write_png path (Image.to_rgb8 scene.settings.encoding img)

let render o =
  try
    validate o;
    let options =
      { Parse.default_options with include_dirs = o.include_dirs; image_width = o.width;
        image_height = o.height }
    in
    let t0 = Unix.gettimeofday () in
    match compile ~options o.scene with
    | Error d ->
        prerr_string (Diag.to_string d);
        1
    | Ok (scene, files) ->
        let out = output_path o in
        if List.exists (fun f -> same_file f out) files then
          fail "the output %s is the scene or one of its include files: refusing to overwrite it" out;
        let dir = Filename.dirname out in
        if not (Sys.file_exists dir && Sys.is_directory dir) then
          fail "cannot write %s: folder %s does not exist" out dir;
        let domains = match o.domains with Some d -> d | None -> Domain.recommended_domain_count () in
        if o.mode = Whitted && o.spp <> 64 && not o.quiet then
          prerr_endline "camlray: warning: --spp is ignored in whitted mode";
        if o.mode = Monte_carlo && o.aa <> None && not o.quiet then
          prerr_endline "camlray: warning: --aa is ignored in mc mode";
        let scene =
          match (o.mode, o.depth) with
          | Whitted, Some d -> { scene with settings = { scene.settings with max_trace_level = d } }
          | _ -> scene
        in
        let max_depth = match o.depth with Some d -> d | None -> 16 in
        let width = o.width and height = o.height in
        let pixel =
          match o.mode with
          | Whitted -> Whitted.pixel scene ~width ~height
          | Monte_carlo -> Path.pixel scene ~width ~height ~seed:o.seed ~spp:o.spp ~max_depth
        in
        let tty = Unix.isatty Unix.stderr && not o.quiet in
        let t1 = Unix.gettimeofday () in
        let last = ref 0. in
        let progress ~done_ ~total =
          let now = Unix.gettimeofday () in
          if tty && (now -. !last > 0.1 || done_ = total) then (
            last := now;
            progress_bar ~start:t1 ~done_ ~total)
        in
        let cancelled () = Atomic.get cancelled in
        let img =
          with_signals (fun () ->
              match (o.mode, o.aa) with
              | Whitted, Some threshold ->
                  Aa.render ~domains ~progress ~cancelled ~width ~height ~threshold
                    ~depth:o.aa_depth (Whitted.sample scene ~width ~height)
              | _ -> Render.image ~domains ~progress ~cancelled ~width ~height pixel)
        in
        if tty then prerr_newline ();
        let t2 = Unix.gettimeofday () in
        (try write_image out scene img
         with Sys_error e | Failure e -> fail "cannot write %s: %s" out e);
        let t3 = Unix.gettimeofday () in
        if not o.quiet then begin
          let samples = float_of_int (width * height * match o.mode with Whitted -> 1 | Monte_carlo -> o.spp) in
          Printf.eprintf
            "camlray: wrote %s (%dx%d, %s, %d domain%s) in %.2f s (parse %.2f s, render %.2f s, %.2f M samples/s, write %.2f s)\n%!"
            out width height
            (match o.mode with Whitted -> "whitted" | Monte_carlo -> Printf.sprintf "mc %d spp" o.spp)
            domains (if domains = 1 then "" else "s") (t3 -. t0) (t1 -. t0) (t2 -. t1)
            (samples /. (t2 -. t1) /. 1e6) (t3 -. t2)
        end;
        0
  with
  | Fail msg ->
      prerr_endline ("camlray: " ^ msg);
      1
  | Render.Cancelled ->
      prerr_endline "camlray: interrupted; nothing was written";
      130

let check path include_dirs =
  let options = { Parse.default_options with include_dirs } in
  try
    match compile ~options (Some path) with
    | Error d ->
        prerr_string (Diag.to_string d);
        1
    | Ok (scene, _) ->
        Printf.printf "%s: ok (%d objects, %d lights)\n" path (Array.length scene.objects)
          (Array.length scene.lights);
        0
  with Fail msg ->
    prerr_endline ("camlray: " ^ msg);
    1
