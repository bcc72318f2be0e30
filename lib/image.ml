(* Frame buffer, 8-bit encodings, PNG/PPM/PFM files and image metrics. *)

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
type par = int -> (int -> unit) -> unit

let sequential n f =
  for i = 0 to n - 1 do
    f i
  done

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

type table = { th : float array; start : Bytes.t }

let table enc =
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

(* Rows per band of the encoder's parallel parts: fixed, so that the file
   does not depend on the number of domains. *)
let band_rows = 64

let bands h = (h + band_rows - 1) / band_rows

let to_rgb8 ?(par = sequential) enc (img : t) =
  let data = Bytes.create (img.w * img.h * 3) in
  let th = table enc in
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

(* {2 PNG writing} *)

let png_signature = "\x89PNG\r\n\x1a\n"

(* CRC-32 (ISO 3309, as PNG uses) of [s]; [crc] chains calls. zlib's. *)
let crc32 ?(crc = 0) s =
  Int32.to_int (Zlib.update_crc_string (Int32.of_int crc) s 0 (String.length s)) land 0xFFFFFFFF

let be32 n =
  let b = Bytes.create 4 in
  Bytes.set_int32_be b 0 (Int32.of_int n);
  Bytes.to_string b

let get_u32 s i = Int32.to_int (String.get_int32_be s i) land 0xFFFFFFFF

let output_chunk oc typ data =
  output_string oc (be32 (String.length data));
  output_string oc typ;
  output_string oc data;
  output_string oc (be32 (crc32 ~crc:(crc32 typ) data))

(* Adler-32 (RFC 1950) of [len] bytes of [s] from [pos]. *)
let adler32 s pos len =
  let base = 65521 in
  let s1 = ref 1 and s2 = ref 0 in
  let i = ref pos and stop = pos + len in
  while !i < stop do
    (* the sums are reduced every 5552 bytes, as zlib does *)
    let n = min 5552 (stop - !i) in
    for j = !i to !i + n - 1 do
      s1 := !s1 + Char.code (String.unsafe_get s j);
      s2 := !s2 + !s1
    done;
    s1 := !s1 mod base;
    s2 := !s2 mod base;
    i := !i + n
  done;
  (!s2 lsl 16) lor !s1

(* The Adler-32 of a concatenation from its parts' sums: the second
   part's first sum is shifted by the first part's (less the initial 1),
   its second sum by [len2] times the first part's first sum. *)
let adler32_combine a1 a2 len2 =
  let base = 65521 in
  let r = len2 mod base in
  let a1lo = a1 land 0xFFFF and a1hi = (a1 lsr 16) land 0xFFFF in
  let a2lo = a2 land 0xFFFF and a2hi = (a2 lsr 16) land 0xFFFF in
  let s1 = (a1lo + a2lo + base - 1) mod base in
  let s2 = ((r * a1lo) + a1hi + a2hi + base - r) mod base in
  (s2 lsl 16) lor s1

(* Raw deflate (level 6) of [len] bytes of [s] from [pos]; a part that is
   not the last ends with a sync flush (byte-aligned, no final block), so
   that independent parts concatenate into one stream. *)
let deflate_part ~last s pos len =
  let zs = Zlib.deflate_init 6 false in
  let out = Buffer.create ((len / 2) + 64) and buf = Bytes.create 65536 in
  let flush = if last then Zlib.Z_FINISH else Zlib.Z_SYNC_FLUSH in
  let rec go pos len =
    let fin, used_in, used_out = Zlib.deflate_string zs s pos len buf 0 (Bytes.length buf) flush in
    Buffer.add_subbytes out buf 0 used_out;
    (* finished, or all input taken and the flush fitted in the buffer *)
    if not (fin || (used_in = len && used_out < Bytes.length buf)) then go (pos + used_in) (len - used_in)
  in
  go pos len;
  (* zlib frees an unfinished stream but reports it (Z_DATA_ERROR) *)
  (try Zlib.deflate_end zs with Zlib.Error _ when not last -> ());
  Buffer.contents out

(* The zlib stream (RFC 1950) of [s], compressed in independent parts cut
   at the offsets [cuts] (increasing, strictly inside [s]). *)
let deflate ?(par = sequential) ?(cuts = [||]) s =
  let bounds = Array.concat [ [| 0 |]; cuts; [| String.length s |] ] in
  let n = Array.length bounds - 1 in
  let parts = Array.make n "" and sums = Array.make n 1 in
  par n (fun i ->
      let pos = bounds.(i) and len = bounds.(i + 1) - bounds.(i) in
      parts.(i) <- deflate_part ~last:(i = n - 1) s pos len;
      sums.(i) <- adler32 s pos len);
  let sum = ref sums.(0) in
  for i = 1 to n - 1 do
    sum := adler32_combine !sum sums.(i) (bounds.(i + 1) - bounds.(i))
  done;
  (* CMF 0x78: deflate with a 32K window; FLG 0x9C: the default level,
     check bits making CMF*256+FLG a multiple of 31 *)
  String.concat "" (("\x78\x9c" :: Array.to_list parts) @ [ be32 !sum ])

let paeth a b c =
  let p = a + b - c in
  let pa = abs (p - a) and pb = abs (p - b) and pc = abs (p - c) in
  if pa <= pb && pa <= pc then a else if pb <= pc then b else c

(* |v| of a residual as a signed byte (v mod 256 in [-128, 127]), without
   a branch: the cost of a filtered byte *)
let[@inline] cost v =
  let v = v land 0xFF in
  if v < 128 then v else 256 - v

(* Filters one scanline into [out] at [y * (stride + 1)]: the filter (None,
   Sub, Up, Average, Paeth) with the smallest sum of absolute signed
   residuals (the first such, in that order), the usual libpng heuristic.
   The row above the first is zeros; the bytes left of the first pixel
   too (the first pixel's loop apart, so that the others test nothing). *)
let filter_row (im : rgb8) out y =
  let stride = im.w * 3 in
  let d = im.data in
  let row = y * stride in
  let above, prev = if y = 0 then (Bytes.make stride '\000', 0) else (d, (y - 1) * stride) in
  let first = min 3 stride in
  let c0 = ref 0 and c1 = ref 0 and c2 = ref 0 and c3 = ref 0 and c4 = ref 0 in
  for i = 0 to first - 1 do
    let x = Char.code (Bytes.unsafe_get d (row + i)) and b = Char.code (Bytes.unsafe_get above (prev + i)) in
    c0 := !c0 + cost x;
    c1 := !c1 + cost x;
    c2 := !c2 + cost (x - b);
    c3 := !c3 + cost (x - (b / 2));
    c4 := !c4 + cost (x - paeth 0 b 0)
  done;
  for i = first to stride - 1 do
    let x = Char.code (Bytes.unsafe_get d (row + i)) and b = Char.code (Bytes.unsafe_get above (prev + i)) in
    let a = Char.code (Bytes.unsafe_get d (row + i - 3)) and c = Char.code (Bytes.unsafe_get above (prev + i - 3)) in
    c0 := !c0 + cost x;
    c1 := !c1 + cost (x - a);
    c2 := !c2 + cost (x - b);
    c3 := !c3 + cost (x - ((a + b) / 2));
    c4 := !c4 + cost (x - paeth a b c)
  done;
  let ft = ref 0 and best = ref !c0 in
  let pick k c = if c < !best then (best := c; ft := k) in
  pick 1 !c1;
  pick 2 !c2;
  pick 3 !c3;
  pick 4 !c4;
  let ft = !ft and o = y * (stride + 1) + 1 in
  Bytes.unsafe_set out (o - 1) (Char.unsafe_chr ft);
  for i = 0 to stride - 1 do
    let x = Char.code (Bytes.unsafe_get d (row + i)) and b = Char.code (Bytes.unsafe_get above (prev + i)) in
    let a = if i >= 3 then Char.code (Bytes.unsafe_get d (row + i - 3)) else 0
    and c = if i >= 3 then Char.code (Bytes.unsafe_get above (prev + i - 3)) else 0 in
    let pred = match ft with 0 -> 0 | 1 -> a | 2 -> b | 3 -> (a + b) / 2 | _ -> paeth a b c in
    Bytes.unsafe_set out (o + i) (Char.unsafe_chr ((x - pred) land 0xFF))
  done

(* The PNG image data: the filtered scanlines, compressed in bands of
   [band_rows] rows (the bands filtered and compressed in parallel). *)
let image_data ?(par = sequential) (im : rgb8) =
  let stride = (im.w * 3) + 1 in
  let out = Bytes.create (stride * im.h) in
  let nb = bands im.h in
  par nb (fun b ->
      for y = b * band_rows to min im.h ((b + 1) * band_rows) - 1 do
        filter_row im out y
      done);
  deflate ~par ~cuts:(Array.init (nb - 1) (fun b -> (b + 1) * band_rows * stride)) (Bytes.unsafe_to_string out)

(* A tEXt keyword is 1-79 Latin-1 bytes without NUL; the text has no NUL. *)
let check_text (k, v) =
  if
    k = "" || String.length k > 79 || String.contains k '\000'
    || String.contains v '\000'
  then invalid_arg ("Image.write_png: invalid tEXt entry " ^ String.escaped k)

let write_png ?par ?(text = []) path (im : rgb8) =
  check_rgb8 "Image.write_png" im;
  List.iter check_text text;
  let idat = image_data ?par im in
  write_atomic path (fun oc ->
      output_string oc png_signature;
      (* width, height, depth 8, colour type 2 (RGB), deflate, filter
         method 0, no interlace *)
      output_chunk oc "IHDR" (be32 im.w ^ be32 im.h ^ "\008\002\000\000\000");
      List.iter (fun (k, v) -> output_chunk oc "tEXt" (k ^ "\000" ^ v)) text;
      output_chunk oc "IDAT" idat;
      output_chunk oc "IEND" "")

(* {2 Reading} *)

let read_file path =
  try In_channel.with_open_bin path In_channel.input_all
  with Sys_error m -> failwith (with_path path m)

(* The chunks (type, data) of the PNG [s] before IEND, CRCs checked. *)
let png_chunks s =
  let n = String.length s in
  if not (String.starts_with ~prefix:png_signature s) then
    failwith "not a PNG file";
  let rec chunks pos acc =
    if pos + 12 > n then failwith "truncated PNG (no IEND chunk)";
    let len = get_u32 s pos in
    if len > n - pos - 12 then failwith "truncated PNG chunk";
    let typ = String.sub s (pos + 4) 4 and data = String.sub s (pos + 8) len in
    if get_u32 s (pos + 8 + len) <> crc32 ~crc:(crc32 typ) data then
      failwith ("bad CRC in " ^ typ ^ " chunk");
    if typ = "IEND" then List.rev acc
    else chunks (pos + 12 + len) ((typ, data) :: acc)
  in
  chunks 8 []

let png_text path =
  let s = read_file path in
  naming path @@ fun () ->
  List.filter_map
    (fun (typ, data) ->
      if typ <> "tEXt" then None
      else
        match String.index_opt data '\000' with
        | None -> Some (data, "")
        | Some i ->
            let n = String.length data in
            Some (String.sub data 0 i, String.sub data (i + 1) (n - i - 1)))
    (png_chunks s)

(* zlib-inflates [s], failing on corrupt or truncated data or on more than
   [limit] bytes of output. *)
let inflate ~limit s =
  let zs = Zlib.inflate_init true and buf = Bytes.create 65536 in
  let out = Buffer.create (min limit (4 * String.length s)) in
  let rec go pos =
    let fin, used_in, used_out =
      Zlib.inflate_string zs s pos (String.length s - pos) buf 0
        (Bytes.length buf) Z_SYNC_FLUSH
    in
    Buffer.add_subbytes out buf 0 used_out;
    if Buffer.length out > limit then failwith "too much image data";
    if not fin then
      if used_in = 0 && used_out = 0 then failwith "truncated image data"
      else go (pos + used_in)
  in
  Fun.protect
    ~finally:(fun () -> Zlib.inflate_end zs)
    (fun () ->
      try go 0
      with Zlib.Error (_, m) -> failwith ("corrupt image data (" ^ m ^ ")"));
  Buffer.contents out

let adam7 =
  [ (0, 0, 8, 8); (4, 0, 8, 8); (0, 4, 4, 8); (2, 0, 4, 4);
    (0, 2, 2, 4); (1, 0, 2, 2); (0, 1, 1, 2) ]

(* camlimages' reader crashes (it returns an invalid value) when libpng
   fails while decoding the pixels, so everything libpng could fail on
   there is checked first: chunk structure and CRCs, IHDR, known critical
   chunks, contiguous IDATs, the zlib stream, its exact length and the row
   filter bytes. Returns the colour type. *)
let check_png s =
  let chunks = png_chunks s in
  let ihdr =
    match chunks with
    | ("IHDR", d) :: _ when String.length d = 13 -> d
    | _ -> failwith "no IHDR chunk"
  in
  let w = get_u32 ihdr 0 and h = get_u32 ihdr 4 in
  let depth = Char.code ihdr.[8] and ct = Char.code ihdr.[9] in
  let channels =
    match (ct, depth) with
    | 0, (1 | 2 | 4 | 8 | 16) | 3, (1 | 2 | 4 | 8) -> 1
    | 2, (8 | 16) -> 3
    | 4, (8 | 16) -> 2
    | 6, (8 | 16) -> 4
    | _ -> failwith (Printf.sprintf "bad colour type %d, depth %d" ct depth)
  in
  if w < 1 || h < 1 || w > 1 lsl 24 || h > 1 lsl 24 || w * h > 1 lsl 28 then
    failwith "bad or too large size";
  if ihdr.[10] <> '\000' || ihdr.[11] <> '\000' || Char.code ihdr.[12] > 1
  then failwith "bad IHDR";
  List.iter
    (fun (typ, _) ->
      let critical = typ.[0] >= 'A' && typ.[0] <= 'Z' in
      if critical && not (List.mem typ [ "IHDR"; "PLTE"; "IDAT" ]) then
        failwith ("unknown critical chunk " ^ typ))
    chunks;
  if ct = 3 && not (List.mem_assoc "PLTE" chunks) then
    failwith "no PLTE chunk";
  (* the size of each pass: the image, or Adam7's seven sub-images *)
  let passes =
    if ihdr.[12] = '\000' then [ (w, h) ]
    else
      List.filter_map
        (fun (x0, y0, dx, dy) ->
          let pw = (w - x0 + dx - 1) / dx and ph = (h - y0 + dy - 1) / dy in
          if pw > 0 && ph > 0 then Some (pw, ph) else None)
        adam7
  in
  let row_bytes pw = 1 + (((pw * channels * depth) + 7) / 8) in
  let expected =
    List.fold_left (fun n (pw, ph) -> n + (ph * row_bytes pw)) 0 passes
  in
  let rec idat acc = function
    | ("IDAT", d) :: rest -> idat (d :: acc) rest
    | rest ->
        if List.mem_assoc "IDAT" rest then failwith "IDAT chunks not together";
        String.concat "" (List.rev acc)
  in
  let rec first_idat = function
    | ("IDAT", _) :: _ as l -> idat [] l
    | _ :: rest -> first_idat rest
    | [] -> failwith "no IDAT chunk"
  in
  let raw = inflate ~limit:expected (first_idat chunks) in
  if String.length raw <> expected then failwith "not enough image data";
  ignore
    (List.fold_left
       (fun pos (pw, ph) ->
         for r = 0 to ph - 1 do
           if Char.code raw.[pos + (r * row_bytes pw)] > 4 then
             failwith "bad row filter type"
         done;
         pos + (ph * row_bytes pw))
       0 passes);
  ct

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
  let ct = check_png s in
  let load f =
    match f path [] with
    | img -> of_camlimages img
    | exception (Sys_error m | Invalid_argument m) -> failwith m
    | exception Images.Wrong_file_type -> failwith "unreadable PNG"
  in
  (* load_as_rgb24 refuses palettes with transparency; Png.load reads them *)
  try load Png.load_as_rgb24 with Failure _ when ct = 3 -> load Png.load

(* PPM P6 or P3, any maxval up to 65535, scaled to 8 bits with rounding. *)
let read_ppm s =
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
  let w = int "width" in
  let h = int "height" in
  let maxval = int "maxval" in
  if w <= 0 || h <= 0 || w * h > 1 lsl 28 then failwith "bad or too large size";
  if maxval < 1 || maxval > 65535 then failwith "maxval out of 1..65535";
  let count = w * h * 3 in
  let sample =
    if s.[1] = '3' then fun _ -> int "sample"
    else begin
      (* exactly one whitespace byte ends the header of a binary PPM *)
      if !pos >= n || not (is_space s.[!pos]) then failwith "bad header";
      let base = !pos + 1 and bytes = if maxval < 256 then 1 else 2 in
      if n - base < count * bytes then failwith "truncated pixel data";
      if bytes = 1 then fun i -> Char.code s.[base + i]
      else fun i -> String.get_uint16_be s (base + (2 * i))
    end
  in
  let data = Bytes.create count in
  for i = 0 to count - 1 do
    let v = sample i in
    if v > maxval then failwith "sample exceeds maxval";
    Bytes.set_uint8 data i (((v * 255) + (maxval / 2)) / maxval)
  done;
  { w; h; data }

let read path =
  let s = read_file path in
  if String.starts_with ~prefix:png_signature s then read_png path s
  else if String.starts_with ~prefix:"P6" s || String.starts_with ~prefix:"P3" s
  then naming path (fun () -> read_ppm s)
  else failwith (path ^ ": unknown image format (expected PNG or PPM P3/P6)")

(* {1 Metrics} *)

let same_size fn (a : rgb8) (b : rgb8) =
  check_rgb8 fn a;
  check_rgb8 fn b;
  if a.w <> b.w || a.h <> b.h then
    invalid_arg
      (Printf.sprintf "%s: sizes differ (%dx%d vs %dx%d)" fn a.w a.h b.w b.h)

let psnr a b =
  same_size "Image.psnr" a b;
  let se = ref 0 in
  Bytes.iteri
    (fun i c ->
      let d = Char.code c - Bytes.get_uint8 b.data i in
      se := !se + (d * d))
    a.data;
  if !se = 0 then infinity
  else
    let mse = float !se /. float (Bytes.length a.data) in
    10. *. log10 (255. *. 255. /. mse)

let luma (im : rgb8) =
  Array.init (im.w * im.h) (fun i ->
      let c k = float (Bytes.get_uint8 im.data ((3 * i) + k)) in
      (0.2126 *. c 0) +. (0.7152 *. c 1) +. (0.0722 *. c 2))

(* The normalised Gaussian, sigma 1.5, radius 5 (scipy's truncate = 3.5). *)
let gauss =
  let g = Array.init 11 (fun k -> exp (-.float ((k - 5) * (k - 5)) /. 4.5)) in
  let s = Array.fold_left ( +. ) 0. g in
  Array.map (fun v -> v /. s) g

(* The Gaussian-weighted means of the 11x11 windows of the [w] x [h] plane
   [p] that fit inside it: a [(w - 10) x (h - 10)] plane, computed by a
   horizontal then a vertical pass. *)
let window_means w h p =
  let ow = w - 10 and oh = h - 10 in
  let sum get =
    let s = ref 0. in
    for k = 0 to 10 do
      s := !s +. (gauss.(k) *. get k)
    done;
    !s
  in
  let rows =
    Array.init (ow * h) (fun i ->
        let r = i / ow and c = i mod ow in
        sum (fun k -> p.((r * w) + c + k)))
  in
  Array.init (ow * oh) (fun i ->
      let r = i / ow and c = i mod ow in
      sum (fun k -> rows.(((r + k) * ow) + c)))

let ssim a b =
  same_size "Image.ssim" a b;
  if a.w < 11 || a.h < 11 then invalid_arg "Image.ssim: smaller than 11x11";
  let x = luma a and y = luma b in
  let means p = window_means a.w a.h p in
  let mx = means x and my = means y in
  let prod u v = means (Array.map2 ( *. ) u v) in
  let exx = prod x x and eyy = prod y y and exy = prod x y in
  let c1 = (0.01 *. 255.) ** 2. and c2 = (0.03 *. 255.) ** 2. in
  let total = ref 0. in
  Array.iteri
    (fun i mx ->
      let my = my.(i) in
      let vx = exx.(i) -. (mx *. mx) and vy = eyy.(i) -. (my *. my) in
      let cov = exy.(i) -. (mx *. my) in
      total :=
        !total
        +. ((2. *. mx *. my) +. c1) *. ((2. *. cov) +. c2)
           /. (((mx *. mx) +. (my *. my) +. c1) *. (vx +. vy +. c2)))
    mx;
  !total /. float (Array.length mx)

let max_diff a b =
  same_size "Image.max_diff" a b;
  let m = ref 0 in
  Bytes.iteri
    (fun i c -> m := max !m (abs (Char.code c - Bytes.get_uint8 b.data i)))
    a.data;
  !m

let diff_image ?(gain = 4) a b =
  same_size "Image.diff_image" a b;
  if gain < 0 then invalid_arg "Image.diff_image: negative gain";
  let scaled i c =
    Char.chr (min 255 (gain * abs (Char.code c - Bytes.get_uint8 b.data i)))
  in
  { a with data = Bytes.mapi scaled a.data }

let side_by_side = function
  | [] -> invalid_arg "Image.side_by_side: no images"
  | ims ->
      List.iter (check_rgb8 "Image.side_by_side") ims;
      let w = List.fold_left (fun s (im : rgb8) -> s + im.w) 0 ims in
      let h = List.fold_left (fun m (im : rgb8) -> max m im.h) 0 ims in
      let data = Bytes.make (w * h * 3) '\000' in
      let place x0 (im : rgb8) =
        for y = 0 to im.h - 1 do
          Bytes.blit im.data (y * im.w * 3) data (((y * w) + x0) * 3) (im.w * 3)
        done;
        x0 + im.w
      in
      ignore (List.fold_left place 0 ims);
      { w; h; data }
