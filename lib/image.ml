(* Frame buffer, 8-bit encodings, image files. *)

type t = { w : int; h : int; px : Float.Array.t }

let create w h =
  if w <= 0 || h <= 0 then invalid_arg "Image.create";
  { w; h; px = Float.Array.make (w * h * 3) 0. }

(* Every pixel to be written by the caller: the pages are first touched
   by the rendering domains, in parallel, not all by one domain here. *)
let create_unset w h =
  if w <= 0 || h <= 0 then invalid_arg "Image.create_unset";
  { w; h; px = Float.Array.create (w * h * 3) }

let width t = t.w
let height t = t.h

let set t x y r g b =
  let i = 3 * ((y * t.w) + x) in
  Float.Array.set t.px i r;
  Float.Array.set t.px (i + 1) g;
  Float.Array.set t.px (i + 2) b

let get_r t x y = Float.Array.get t.px (3 * ((y * t.w) + x))
let get_g t x y = Float.Array.get t.px ((3 * ((y * t.w) + x)) + 1)
let get_b t x y = Float.Array.get t.px ((3 * ((y * t.w) + x)) + 2)

type rgb8 = { w : int; h : int; data : Bytes.t }
type encoding = Srgb | Gamma_srgb of float | Identity

let srgb_encode c =
  if c <= 0.0031308 then 12.92 *. c
  else (1.055 *. Float.pow c (1. /. 2.4)) -. 0.055

(* [par n f] runs [f 0] ... [f (n-1)], in any order, perhaps at once on
   several domains (Render.parallel gives one); the default runs them in
   turn. Each [f i] writes its own part of the result. *)
type par = Png_codec.par

let sequential = Png_codec.sequential

(* The 8-bit value of a linear value [v], by the formula. *)
let quantize enc v =
  let v = if Float.is_nan v then 0. else Float.min 1. (Float.max 0. v) in
  let v =
    match enc with
    | Srgb -> srgb_encode v
    | Gamma_srgb g -> srgb_encode (Float.pow v g)
    | Identity -> v
  in
  int_of_float (Float.round (v *. 255.))

(* The same by table: [th.(k)] is the least float whose value is above
   [k], found by bisecting on the bits of non-negative floats (whose order
   is the order of their bits); the encodings are non-decreasing, so the
   value of [v] is the number of thresholds at or below it: 8 comparisons
   in place of a [pow]. *)
let thresholds enc =
  let q bits = quantize enc (Int64.float_of_bits bits) in
  let one = Int64.bits_of_float 1. in
  Array.init 255 (fun k ->
      if q 0L > k then 0.
      else begin
        (* q lo <= k < q hi *)
        let lo = ref 0L and hi = ref one in
        while Int64.sub !hi !lo > 1L do
          let mid = Int64.add !lo (Int64.div (Int64.sub !hi !lo) 2L) in
          if q mid > k then hi := mid else lo := mid
        done;
        Int64.float_of_bits !hi
      end)

(* how many thresholds are <= v: a binary search over 255 entries *)
let search (th : float array) v =
  if Float.is_nan v then 0
  else begin
    let lo = ref 0 and n = ref 255 in
    while !n > 0 do
      let half = !n / 2 in
      if Array.unsafe_get th (!lo + half) <= v then (
        lo := !lo + half + 1;
        n := !n - half - 1)
      else n := half
    done;
    !lo
  end

(* The search's branches are unpredictable: 8 of them per channel were a
   fifth of a quick render's time. [start] gives the count at the low end
   of each of [buckets] equal parts of [0, 1); a value then passes the
   few thresholds inside its part (at most one for sRGB, whose steepest
   slope, 12.92, puts levels 1/3295 apart). Values at or above 1 are
   above every threshold (the value 1 quantizes to 255); below 0, NaN and
   the rest take the search: the same count in every case. *)
let buckets = 8192

type quantizer = { th : float array; start : Bytes.t }

let quantizer enc =
  let th = thresholds enc in
  { th; start = Bytes.init buckets (fun b -> Char.chr (search th (float b /. float buckets))) }

let[@inline] lookup t v =
  if v >= 0. && v < 1. then begin
    (* exact: scaling by a power of two rounds nothing *)
    let k = ref (Char.code (Bytes.unsafe_get t.start (int_of_float (v *. float buckets)))) in
    while !k < 255 && Array.unsafe_get t.th !k <= v do incr k done;
    !k
  end
  else if v >= 1. then 255
  else search t.th v

(* quantized in the PNG encoder's bands of rows *)
let band_rows = Png_codec.band_rows
let bands = Png_codec.bands

let create_rgb8 w h =
  if w <= 0 || h <= 0 then invalid_arg "Image.create_rgb8";
  { w; h; data = Bytes.create (w * h * 3) }

let set_rgb8 q (im : rgb8) x y r g b =
  let i = 3 * ((y * im.w) + x) in
  Bytes.set im.data i (Char.unsafe_chr (lookup q r));
  Bytes.set im.data (i + 1) (Char.unsafe_chr (lookup q g));
  Bytes.set im.data (i + 2) (Char.unsafe_chr (lookup q b))

let to_rgb8 ?(par = sequential) enc (img : t) =
  let data = Bytes.create (img.w * img.h * 3) in
  let th = quantizer enc in
  let row = img.w * 3 in
  par (bands img.h) (fun b ->
      let i0 = b * band_rows * row and i1 = min img.h ((b + 1) * band_rows) * row in
      for i = i0 to i1 - 1 do
        Bytes.unsafe_set data i (Char.unsafe_chr (lookup th (Float.Array.unsafe_get img.px i)))
      done);
  { w = img.w; h = img.h; data }

(* Checks that [im] is well formed before it is written or compared. *)
let check_rgb8 fn (im : rgb8) =
  if im.w <= 0 || im.h <= 0 || Bytes.length im.data <> im.w * im.h * 3 then
    invalid_arg (fn ^ ": malformed rgb8 image")

(* {1 Files} *)

(* Prefixes [msg] with [path] unless it already starts with it. *)
let with_path path msg =
  if String.starts_with ~prefix:path msg then msg else path ^ ": " ^ msg

(* Runs [f], naming [path] in its [Failure]. *)
let naming path f = try f () with Failure m -> failwith (with_path path m)
let rng = Domain.DLS.new_key Random.State.make_self_init

(* Creates ".NAME.XXXXXX.tmp" beside [path] with O_EXCL (mode 0666 less the
   umask, where [Filename.temp_file] would give 0600). *)
let open_temp path =
  let dir = Filename.dirname path and base = Filename.basename path in
  let rec go tries =
    let r = Random.State.bits (Domain.DLS.get rng) land 0xFFFFFF in
    let tmp = Filename.concat dir (Printf.sprintf ".%s.%06x.tmp" base r) in
    match Unix.openfile tmp [ O_WRONLY; O_CREAT; O_EXCL; O_CLOEXEC ] 0o666 with
    | fd -> (tmp, fd)
    | exception Unix.Unix_error (EEXIST, _, _) when tries > 0 -> go (tries - 1)
    | exception Unix.Unix_error (e, _, _) ->
        raise
          (Sys_error
             (Printf.sprintf "%s: cannot create a temporary file in %s: %s" path
                dir (Unix.error_message e)))
  in
  go 100

let write_atomic path f =
  let tmp, fd = open_temp path in
  let oc = Unix.out_channel_of_descr fd in
  set_binary_mode_out oc true;
  try
    f oc;
    flush oc;
    let intended = pos_out oc in
    Unix.fsync fd;
    close_out oc;
    let written = (Unix.stat tmp).st_size in
    if written <> intended then
      failwith (Printf.sprintf "wrote %d bytes instead of %d" written intended);
    Sys.rename tmp path
  with e ->
    let bt = Printexc.get_raw_backtrace () in
    close_out_noerr oc;
    (try Sys.remove tmp with Sys_error _ -> ());
    let e =
      match e with
      | Sys_error m -> Sys_error (with_path path m)
      | Failure m -> Failure (with_path path m)
      | Unix.Unix_error (err, fn, _) ->
          let m = Unix.error_message err in
          Sys_error (Printf.sprintf "%s: %s: %s" path fn m)
      | e -> e
    in
    Printexc.raise_with_backtrace e bt

let write_ppm path (im : rgb8) =
  check_rgb8 "Image.write_ppm" im;
  write_atomic path (fun oc ->
      Printf.fprintf oc "P6\n%d %d\n255\n" im.w im.h;
      output_bytes oc im.data)

let write_pfm path (img : t) =
  write_atomic path (fun oc ->
      Printf.fprintf oc "PF\n%d %d\n-1.0\n" img.w img.h;
      let row = Bytes.create (img.w * 12) in
      for y = img.h - 1 downto 0 do
        for i = 0 to (img.w * 3) - 1 do
          let v = Float.Array.get img.px ((y * img.w * 3) + i) in
          Bytes.set_int32_le row (4 * i) (Int32.bits_of_float v)
        done;
        output_bytes oc row
      done)

let write_png ?par ?text path (im : rgb8) =
  check_rgb8 "Image.write_png" im;
  let png = Png_codec.encode ?par ?text im.w im.h im.data in
  write_atomic path (fun oc -> output_string oc png)

(* {2 Reading} *)

let read_file path =
  try In_channel.with_open_bin path In_channel.input_all
  with Sys_error m -> failwith (with_path path m)

let png_text path =
  let s = read_file path in
  naming path @@ fun () -> Png_codec.text s

(* Any camlimages image as packed RGB, alpha dropped. *)
let of_camlimages (img : Images.t) : rgb8 =
  let rgb24 (b : Rgb24.t) =
    { w = b.width; h = b.height; data = Rgb24.dump b }
  in
  match img with
  | Rgb24 b -> rgb24 b
  | Index8 b -> rgb24 (Index8.to_rgb24 b)
  | Index16 b -> rgb24 (Index16.to_rgb24 b)
  | Rgba32 b ->
      let src = Rgba32.dump b and n = b.width * b.height in
      let data = Bytes.create (n * 3) in
      for i = 0 to n - 1 do
        Bytes.blit src (4 * i) data (3 * i) 3
      done;
      { w = b.width; h = b.height; data }
  | Cmyk32 _ -> failwith "CMYK images are not supported"

let read_png path s =
  naming path @@ fun () ->
  let ct = Png_codec.check s in
  let load f =
    match f path [] with
    | img -> of_camlimages img
    | exception (Sys_error m | Invalid_argument m) -> failwith m
    | exception Images.Wrong_file_type -> failwith "unreadable PNG"
  in
  (* load_as_rgb24 refuses palettes with transparency; Png.load reads them *)
  try load Png.load_as_rgb24 with Failure _ when ct = 3 -> load Png.load

let is_gif s = String.starts_with ~prefix:"GIF87a" s || String.starts_with ~prefix:"GIF89a" s

(* a GIF's first image, its palette kept: libgif through camlimages *)
let gif_index8 path =
  naming path @@ fun () ->
  match Gif.load_first path [] with
  | Index8 b -> b
  | _ -> failwith "not a palette image"
  | exception (Sys_error m | Invalid_argument m) -> failwith m
  | exception Not_found -> failwith "damaged GIF"

let read_gif path = of_camlimages (Index8 (gif_index8 path))

let gif_indices path =
  let b = gif_index8 path in
  (b.width, b.height, Index8.dump b, b.colormap.map |> Array.length)

let read_palette path =
  let s = read_file path in
  if is_gif s then Some (gif_indices path)
  else if not (String.starts_with ~prefix:Png_codec.signature s) then None
  else
    naming path @@ fun () ->
    (* a palette PNG has its PLTE chunk (Png_codec.check sees to it) *)
    if Png_codec.check s <> 3 then None
    else
      let n = match Png_codec.chunk s "PLTE" with Some p -> String.length p / 3 | None -> failwith "no PLTE chunk" in
      match Png.load path [] with
      | Index8 b -> Some (b.width, b.height, Index8.dump b, n)
      | _ -> None
      | exception (Sys_error m | Invalid_argument m) -> failwith m
      | exception Images.Wrong_file_type -> failwith "unreadable PNG"

let read_indices path = Option.map (fun (w, h, idx, _) -> (w, h, idx)) (read_palette path)

(* A palette's alphas come from its tRNS chunk (entries past its end are
   opaque), camlimages keeping only one transparent index; an alpha
   channel from camlimages' RGBA image (grey and alpha too) *)
let read_alpha path =
  let s = read_file path in
  if not (String.starts_with ~prefix:Png_codec.signature s) then None
  else
    let ct = naming path (fun () -> Png_codec.check s) in
    match ct with
    | 3 -> (
        let trns = naming path (fun () -> Option.value ~default:"" (Png_codec.chunk s "tRNS")) in
        let n = String.length trns in
        match read_indices path with
        | Some (_, _, idx) -> Some (Bytes.map (fun c -> if Char.code c < n then trns.[Char.code c] else '\255') idx)
        | None -> naming path (fun () -> failwith "unreadable palette"))
    | 4 | 6 -> (
        naming path @@ fun () ->
        match Png.load path [] with
        | Rgba32 b ->
            let src = Rgba32.dump b in
            Some (Bytes.init (b.width * b.height) (fun i -> Bytes.get src ((4 * i) + 3)))
        | _ -> failwith "no alpha channel read"
        | exception (Sys_error m | Invalid_argument m) -> failwith m
        | exception Images.Wrong_file_type -> failwith "unreadable PNG")
    | _ -> None

(* A PNM file (P2, P3 text; P5, P6 binary): its size, samples per pixel
   (1 grey, 3 colour), maxval and its samples in order, read on demand *)
let pnm s ~max_pixels =
  let n = String.length s and pos = ref 2 in
  let is_space c = String.contains " \t\n\r\011\012" c in
  let rec skip () =
    if !pos < n && is_space s.[!pos] then (incr pos; skip ())
    else if !pos < n && s.[!pos] = '#' then begin
      while !pos < n && s.[!pos] <> '\n' do incr pos done;
      skip ()
    end
  in
  let int what =
    skip ();
    let start = !pos in
    while !pos < n && s.[!pos] >= '0' && s.[!pos] <= '9' do incr pos done;
    if !pos = start || !pos - start > 9 then
      failwith ("bad or missing " ^ what);
    int_of_string (String.sub s start (!pos - start))
  in
  let kind = s.[1] in
  let w = int "width" in
  let h = int "height" in
  let maxval = int "maxval" in
  if w <= 0 || h <= 0 || w * h > max_pixels then failwith "bad or too large size";
  if maxval < 1 || maxval > 65535 then failwith "maxval out of 1..65535";
  let channels = if kind = '2' || kind = '5' then 1 else 3 in
  let count = w * h * channels in
  let sample =
    if kind = '2' || kind = '3' then fun _ -> int "sample"
    else begin
      (* exactly one whitespace byte ends the header of a binary PNM *)
      if !pos >= n || not (is_space s.[!pos]) then failwith "bad header";
      let base = !pos + 1 and bytes = if maxval < 256 then 1 else 2 in
      if n - base < count * bytes then failwith "truncated pixel data";
      if bytes = 1 then fun i -> Char.code s.[base + i]
      else fun i -> String.get_uint16_be s (base + (2 * i))
    end
  in
  (w, h, channels, maxval, sample)

(* PPM P6 or P3, any maxval up to 65535, scaled to 8 bits with rounding. *)
let read_ppm s =
  let w, h, _, maxval, sample = pnm s ~max_pixels:(1 lsl 28) in
  let count = w * h * 3 in
  let data = Bytes.create count in
  for i = 0 to count - 1 do
    let v = sample i in
    if v > maxval then failwith "sample exceeds maxval";
    Bytes.set_uint8 data i (((v * 255) + (maxval / 2)) / maxval)
  done;
  { w; h; data }

let is_jpeg s = String.starts_with ~prefix:"\xFF\xD8\xFF" s

(* the number of colour components of a JPEG's frame (1 grey, 3 colour),
   from its first start-of-frame marker *)
let jpeg_components s =
  let n = String.length s in
  let rec go i =
    if i + 4 > n then failwith "JPEG without a frame header"
    else if s.[i] <> '\xFF' then failwith "damaged JPEG markers"
    else
      let m = Char.code s.[i + 1] in
      if m = 0xFF then go (i + 1)
      else if m = 0xD8 || (m >= 0xD0 && m <= 0xD7) || m = 0x01 then go (i + 2)
      else
        let len = (Char.code s.[i + 2] lsl 8) lor Char.code s.[i + 3] in
        (* SOF0 to SOF15, not DHT (C4), JPG (C8) or DAC (CC) *)
        if m >= 0xC0 && m <= 0xCF && m <> 0xC4 && m <> 0xC8 && m <> 0xCC then
          if i + 9 >= n then failwith "truncated JPEG frame header" else Char.code s.[i + 9]
        else if m = 0xDA || m = 0xD9 then failwith "JPEG without a frame header"
        else go (i + 2 + len)
  in
  go 2

let read_jpeg path =
  naming path @@ fun () ->
  match Jpeg.load path [] with
  | img -> of_camlimages img
  | exception (Sys_error m | Invalid_argument m) -> failwith m

let read path =
  let s = read_file path in
  if String.starts_with ~prefix:Png_codec.signature s then read_png path s
  else if String.starts_with ~prefix:"P6" s || String.starts_with ~prefix:"P3" s
  then naming path (fun () -> read_ppm s)
  else if is_jpeg s then read_jpeg path
  else if is_gif s then read_gif path
  else failwith (path ^ ": unknown image format (expected PNG, JPEG, GIF or PPM P3/P6)")
