open Camlray
open Camlray_lang

type mode = Whitted | Monte_carlo

type render_opts = {
  scene : string option;
  output : string option;
  width : int;
  height : int;
  mode : mode;
  spp : int option;
  depth : int option;
  domains : int option;
  seed : int;
  quiet : bool;
  include_dirs : string list;
  allow_read : string list;
  region : string option;
  pov_region : string option;
  frames : (int * int) option;
  clock : float option;
  clock_range : (float * float) option;
  subset : (int * int) option;
  tile_order_seed : int option;
  aa : float option;
  aa_depth : int;
  limits : Supplier.limits;
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
  Option.iter (fun s -> check_range "--spp" s 1 1_000_000) o.spp;
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

let compile ?domains ?(mode = Whitted) ~options scene =
  match load ~options scene with
  | Error d -> Error d
  | Ok (sdl, files) -> (
      match (mode, Compile.mesh_camera_at sdl) with
      | Monte_carlo, Some loc ->
          (* the path tracer takes one camera ray per sample; a mesh
             camera's several rays a pixel, some of them not shot, are
             whitted mode's (Whitted.sample) *)
          Error
            { Diag.loc; chain = [];
              msg = "mesh_camera is rendered in whitted mode only (--mode whitted); mc mode does not support it" }
      | _ ->
          let par = Option.map (fun domains -> Render.parallel ~domains) domains in
          Result.map (fun s -> (s, files)) (Compile.scene ?par sdl))

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

let progress_bar ~label ~start ~done_ ~total =
  let frac = float_of_int done_ /. float_of_int total in
  let elapsed = Unix.gettimeofday () -. start in
  let eta = if frac > 0. then elapsed *. (1. -. frac) /. frac else 0. in
  let width = 30 in
  let filled = int_of_float (frac *. float_of_int width) in
  Printf.eprintf "\r%s[%s%s] %3.0f%%  ETA %5.1fs " (if label = "" then "" else label ^ " ") (String.make filled '#')
    (String.make (width - filled) '.') (100. *. frac) eta;
  flush stderr

let cancelled = Atomic.make false

(* [f ()] with the render cancelled once [limit] seconds have passed (an
   alarm sets the flag the render checks between pixels, as an interrupt
   does); the flag cleared and the alarm disarmed after *)
let with_time_limit limit f =
  match limit with
  | None -> f ()
  | Some secs ->
      let old = Sys.signal Sys.sigalrm (Sys.Signal_handle (fun _ -> Atomic.set cancelled true)) in
      let disarm () = ignore (Unix.setitimer Unix.ITIMER_REAL { Unix.it_interval = 0.; it_value = 0. }) in
      ignore (Unix.setitimer Unix.ITIMER_REAL { Unix.it_interval = 0.; it_value = secs });
      Fun.protect f ~finally:(fun () ->
          disarm ();
          Sys.set_signal Sys.sigalrm old;
          Atomic.set cancelled false)

let with_signals f =
  let handle = Sys.Signal_handle (fun _ -> Atomic.set cancelled true) in
  let old_int = Sys.signal Sys.sigint handle in
  let old_term = Sys.signal Sys.sigterm handle in
  Fun.protect f ~finally:(fun () ->
      Sys.set_signal Sys.sigint old_int;
      Sys.set_signal Sys.sigterm old_term)

(* A render's pixels: linear floats, or the 8-bit values of a PNG or PPM
   made as the pixels are (an eighth of the memory). *)
type frame = Floats of Image.t | Bytes of Image.rgb8

let is_pfm path = String.lowercase_ascii (Filename.extension path) = ".pfm"

let frame_size = function
  | Floats img -> (Image.width img, Image.height img)
  | Bytes im -> (im.w, im.h)

let rgb8 ~par (scene : Scene.t) = function
  | Bytes im -> im
  | Floats img -> Image.to_rgb8 ~par scene.settings.encoding img

let write_image ~domains path (scene : Scene.t) frame =
  let par = Render.parallel ~domains in
  match (frame, String.lowercase_ascii (Filename.extension path)) with
  | Floats img, ".pfm" -> Image.write_pfm path img
  | Bytes _, ".pfm" -> invalid_arg "Driver.write_image: a PFM needs the linear values"
  | _, ".ppm" -> Image.write_ppm path (rgb8 ~par scene frame)
  | _ -> Image.write_png ~par path (rgb8 ~par scene frame)

let frame_name out ~first ~last f =
  ignore first;
  let digits = String.length (string_of_int (abs last)) in
  let ext = Filename.extension out in
  Printf.sprintf "%s%0*d%s" (Filename.remove_extension out) digits f ext

(* The identity of a render: the scene's files and every option that
   changes pixels. Parts of one render share it. *)
let render_id o files ~clock =
  let texts =
    List.map (fun f -> try In_channel.with_open_bin f In_channel.input_all with Sys_error _ -> f) files
  in
  let texts = match o.scene with None -> Default_scene.text :: texts | Some _ -> texts in
  Digest.to_hex
    (Digest.string
       (String.concat "\000"
          (texts
          @ [ Printf.sprintf "%dx%d mode=%s spp=%s depth=%s seed=%d clock=%h" o.width o.height
                (match (o.mode, o.aa) with
                | Whitted, None -> "whitted"
                | Whitted, Some t -> Printf.sprintf "whitted aa=%h/%d" t o.aa_depth
                | Monte_carlo, _ -> "mc")
                (match o.spp with Some s -> string_of_int s | None -> "-")
                (match o.depth with Some d -> string_of_int d | None -> "-")
                o.seed clock ])))

let region_of o =
  match (o.region, o.pov_region) with
  | Some _, Some _ -> fail "give either --region or POV-Ray's +SR/+ER/+SC/+EC, not both"
  | Some r, None -> (
      match Part.parse_region r with Ok r -> Some r | Error e -> fail "%s" e)
  | None, Some p -> (
      match Part.of_pov ~width:o.width ~height:o.height p with Ok r -> Some r | Error e -> fail "%s" e)
  | None, None -> None

let crop img (r : Render.tile) =
  let out = Image.create (r.x1 - r.x0) (r.y1 - r.y0) in
  for y = r.y0 to r.y1 - 1 do
    for x = r.x0 to r.x1 - 1 do
      Image.set out (x - r.x0) (y - r.y0) (Image.get_r img x y) (Image.get_g img x y)
        (Image.get_b img x y)
    done
  done;
  out

let render_frame o ~clock ~frame ~out ~t0 =
  let options =
    { Parse.default_options with include_dirs = o.include_dirs; allow_read = o.allow_read;
      limits = o.limits; image_width = o.width;
      image_height = o.height; clock; frame_number = frame }
  in
  let domains = match o.domains with Some d -> d | None -> Domain.recommended_domain_count () in
  match compile ~domains ~mode:o.mode ~options o.scene with
  | Error d ->
      prerr_string (Diag.to_string d);
      1
  | Ok (scene, files) ->
      if List.exists (fun f -> same_file f out) files then
        fail "the output %s is the scene or one of its include files: refusing to overwrite it" out;
      let dir = Filename.dirname out in
      if not (Sys.file_exists dir && Sys.is_directory dir) then
        fail "cannot write %s: folder %s does not exist" out dir;
      let region = region_of o in
      Option.iter
        (fun r ->
          (match Part.check_region ~width:o.width ~height:o.height r with
          | Ok () -> ()
          | Error e -> fail "%s" e);
          if String.lowercase_ascii (Filename.extension out) <> ".png" then
            fail "a partial render (--region) is written as PNG, which records its placement: %s" out)
        region;
      let scene =
        match (o.mode, o.depth) with
        | Whitted, Some d -> { scene with settings = { scene.settings with max_trace_level = d } }
        | _ -> scene
      in
      let max_depth = match o.depth with Some d -> d | None -> 16 in
      let spp = Option.value o.spp ~default:64 in
      let width = o.width and height = o.height in
      let pixel =
        match o.mode with
        | Whitted -> Whitted.pixel_into scene ~width ~height
        | Monte_carlo -> Path.pixel_into (Path.prepare scene) ~width ~height ~seed:o.seed ~spp ~max_depth
      in
      let tty = Unix.isatty Unix.stderr && not o.quiet in
      (* a progress bar on a terminal, from now, redrawn at most every
         0.1 s *)
      let bar label =
        let start = Unix.gettimeofday () and last = ref 0. in
        fun ~done_ ~total ->
          let now = Unix.gettimeofday () in
          if tty && (now -. !last > 0.1 || done_ = total) then (
            last := now;
            progress_bar ~label ~start ~done_ ~total)
      in
      let t1 = Unix.gettimeofday () in
      (* radiosity's pretrace, before the picture reads its cache *)
      if o.mode = Whitted then begin
        (* a time limit (compare's) stops the pretrace at its next
           progress report *)
        (* the photons first (Whitted.prepare would shoot them), timed *)
        Caustics.prepare ?par:(if domains > 1 then Some (Render.pulled ~domains) else None) scene;
        (match scene.settings.photons with
        | Some { state = { map = Some m; media_map }; _ } ->
            Printf.eprintf "camlray: %d photons stored, gather radius %.4g%s (%.3f s)\n%!" (Photon.size m)
              (Photon.radius m)
              (match media_map with
              | Some mm -> Printf.sprintf "; %d media photons, radius %.4g" (Photon.size mm) (Photon.radius mm)
              | None -> "")
              (Unix.gettimeofday () -. t1)
        | _ -> ());
        let radiosity_bar = bar "radiosity" in
        Whitted.prepare
          ?par:(if domains > 1 then Some (Render.pulled ~domains) else None)
          ~progress:(fun ~done_ ~total ->
            if Atomic.get cancelled then raise Render.Cancelled;
            radiosity_bar ~done_ ~total)
          scene ~width ~height;
        if tty && Option.is_some scene.settings.radiosity then prerr_newline ()
      end;
      (* the picture's own progress, after the pretrace's *)
      let progress = bar "" in
      let cancelled () = Atomic.get cancelled in
      let img =
        with_signals (fun () ->
            match (o.mode, o.aa) with
            | Whitted, Some threshold ->
                (* anti-aliasing works on whole 32x32 blocks: render them,
                   then keep the region *)
                let full =
                  Aa.render_into ~domains ~progress ~cancelled ~width ~height ~threshold
                    ~depth:o.aa_depth (Whitted.sample_into scene ~width ~height)
                in
                Floats (Option.fold ~none:full ~some:(crop full) region)
            | _ when is_pfm out ->
                Floats
                  (Render.image_into ~domains ~progress ~cancelled ?order_seed:o.tile_order_seed ?region
                     ~width ~height pixel)
            | _ ->
                Bytes
                  (Render.rgb8_into ~domains ~progress ~cancelled ?order_seed:o.tile_order_seed ?region
                     ~width ~height scene.settings.encoding pixel))
      in
      if tty then prerr_newline ();
      let t2 = Unix.gettimeofday () in
      (try
         match region with
         | None -> write_image ~domains out scene img
         | Some r ->
             let id = render_id o files ~clock in
             let par = Render.parallel ~domains in
             Image.write_png ~par
               ~text:(Part.text { Part.region = r; width; height; id })
               out (rgb8 ~par scene img)
       with Sys_error e | Failure e -> fail "cannot write %s: %s" out e);
      let t3 = Unix.gettimeofday () in
      if not o.quiet then begin
        let pixels = let w, h = frame_size img in w * h in
        let samples = float_of_int (pixels * match o.mode with Whitted -> 1 | Monte_carlo -> spp) in
        Printf.eprintf
          "camlray: wrote %s (%dx%d%s, %s, %d domain%s) in %.3f s (parse %.3f s, render %.3f s, %.2f M samples/s, write %.3f s)\n%!"
          out width height
          (match region with
          | Some r -> Printf.sprintf " region %d,%d,%d,%d" r.x0 r.y0 r.x1 r.y1
          | None -> "")
          (match (o.mode, o.aa) with
           | Whitted, None -> "whitted"
           | Whitted, Some t -> Printf.sprintf "whitted +A%g +R%d" t o.aa_depth
           | Monte_carlo, _ -> Printf.sprintf "mc %d spp" spp)
          domains (if domains = 1 then "" else "s") (t3 -. t0) (t1 -. t0) (t2 -. t1)
          (samples /. (t2 -. t1) /. 1e6) (t3 -. t2)
      end;
      0

let render o =
  try
    validate o;
    if o.mode = Whitted && o.spp <> None && not o.quiet then
      prerr_endline "camlray: warning: --spp is ignored in whitted mode";
    if o.mode = Monte_carlo && o.aa <> None && not o.quiet then
      prerr_endline "camlray: warning: --aa is ignored in mc mode (samples are spread over each pixel)";
    (let cores = Domain.recommended_domain_count () in
     match o.domains with
     | Some d when d > cores && not o.quiet ->
         (* measured: 4 domains on 2 cores render 1.2 to 1.3 times slower
            than 2 (README, Performance) *)
         Printf.eprintf
           "camlray: warning: %d domains on %d cores: every minor collection stops all domains, so \
            more domains than cores run slower than one per core\n%!"
           d cores
     | _ -> ());
    let out = output_path o in
    (* one pool for every parallel loop of the command, its domains
       starting while the scene is parsed *)
    let domains = match o.domains with Some d -> d | None -> Domain.recommended_domain_count () in
    Render.with_pool ~domains @@ fun () ->
    match o.frames with
    | None ->
        let clock = Option.value o.clock ~default:0. in
        render_frame o ~clock ~frame:0 ~out ~t0:(Unix.gettimeofday ())
    | Some (first, last) ->
        if last < first then fail "--frames %d..%d: the last frame comes before the first" first last;
        let c0, c1 = Option.value o.clock_range ~default:(0., 1.) in
        let lo, hi = match o.subset with Some (a, b) -> (max first a, min last b) | None -> (first, last) in
        if hi < lo then fail "--subset leaves no frame of %d..%d to render" first last;
        let rec go f =
          if f > hi then 0
          else
            let clock =
              if last = first then c0
              else c0 +. ((c1 -. c0) *. float_of_int (f - first) /. float_of_int (last - first))
            in
            let out = if last = first then out else frame_name out ~first ~last f in
            match render_frame o ~clock ~frame:f ~out ~t0:(Unix.gettimeofday ()) with
            | 0 -> go (f + 1)
            | code -> code
        in
        go lo
  with
  | Fail msg ->
      prerr_endline ("camlray: " ^ msg);
      1
  | Render.Cancelled ->
      prerr_endline "camlray: interrupted; nothing was written";
      130

let merge parts out =
  match Part.merge parts out with
  | Ok () -> 0
  | Error e ->
      prerr_endline ("camlray: " ^ e);
      1

let check path include_dirs allow_read limits frame_number clock =
  let options =
    { Parse.default_options with include_dirs; allow_read; limits; frame_number; clock }
  in
  try
    match compile ~domains:(Domain.recommended_domain_count ()) ~options (Some path) with
    | Error d ->
        prerr_string (Diag.to_string d);
        1
    | Ok (scene, _) ->
        Printf.printf "%s: ok (%d objects, %d lights)\n" path (Array.length scene.objects)
          (Array.length (Scene.all_lights scene));
        0
  with Fail msg ->
    prerr_endline ("camlray: " ^ msg);
    1
