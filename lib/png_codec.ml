(* PNG byte streams (see png_codec.mli). *)

type par = int -> (int -> unit) -> unit

let sequential n f =
  for i = 0 to n - 1 do
    f i
  done

(* Rows per band of the encoder's parallel parts: fixed, so that the file
   does not depend on the number of domains. *)
let band_rows = 64

let bands h = (h + band_rows - 1) / band_rows

let signature = "\x89PNG\r\n\x1a\n"

(* CRC-32 (ISO 3309, as PNG uses) of [s]; [crc] chains calls. zlib's. *)
let crc32 ?(crc = 0) s =
  Int32.to_int (Zlib.update_crc_string (Int32.of_int crc) s 0 (String.length s)) land 0xFFFFFFFF

let be32 n =
  let b = Bytes.create 4 in
  Bytes.set_int32_be b 0 (Int32.of_int n);
  Bytes.to_string b

let get_u32 s i = Int32.to_int (String.get_int32_be s i) land 0xFFFFFFFF

let add_chunk b typ data =
  Buffer.add_string b (be32 (String.length data));
  Buffer.add_string b typ;
  Buffer.add_string b data;
  Buffer.add_string b (be32 (crc32 ~crc:(crc32 typ) data))

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

(* the predictor nearest a + b - c, ties to a, then b: its distances
   to a, b and c are |b - c|, |a - c| and |a + b - 2c| *)
let[@inline] paeth a b c =
  let pa = abs (b - c) and pb = abs (a - c) and pc = abs (a + b - c - c) in
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
let filter_row w (d : Bytes.t) out y =
  let stride = w * 3 in
  let row = y * stride in
  let above, prev = if y = 0 then (Bytes.make stride '\000', 0) else (d, (y - 1) * stride) in
  let first = min 3 stride in
  let c0 = ref 0 and c1 = ref 0 and c2 = ref 0 and c3 = ref 0 and c4 = ref 0 in
  for i = 0 to first - 1 do
    let x = Char.code (Bytes.unsafe_get d (row + i)) and b = Char.code (Bytes.unsafe_get above (prev + i)) in
    c0 := !c0 + cost x;
    c1 := !c1 + cost x;
    c2 := !c2 + cost (x - b);
    c3 := !c3 + cost (x - (b lsr 1));
    c4 := !c4 + cost (x - paeth 0 b 0)
  done;
  for i = first to stride - 1 do
    let x = Char.code (Bytes.unsafe_get d (row + i)) and b = Char.code (Bytes.unsafe_get above (prev + i)) in
    let a = Char.code (Bytes.unsafe_get d (row + i - 3)) and c = Char.code (Bytes.unsafe_get above (prev + i - 3)) in
    c0 := !c0 + cost x;
    c1 := !c1 + cost (x - a);
    c2 := !c2 + cost (x - b);
    c3 := !c3 + cost (x - ((a + b) lsr 1));
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
  (* the chosen filter's loop: no choice per byte *)
  let put i v = Bytes.unsafe_set out (o + i) (Char.unsafe_chr (v land 0xFF)) in
  let x i = Char.code (Bytes.unsafe_get d (row + i)) and up i = Char.code (Bytes.unsafe_get above (prev + i)) in
  match ft with
  | 0 -> Bytes.blit d row out o stride
  | 1 ->
      for i = 0 to first - 1 do put i (x i) done;
      for i = first to stride - 1 do put i (x i - x (i - 3)) done
  | 2 -> for i = 0 to stride - 1 do put i (x i - up i) done
  | 3 ->
      for i = 0 to first - 1 do put i (x i - (up i lsr 1)) done;
      for i = first to stride - 1 do put i (x i - ((x (i - 3) + up i) lsr 1)) done
  | _ ->
      for i = 0 to first - 1 do put i (x i - up i) done;
      for i = first to stride - 1 do put i (x i - paeth (x (i - 3)) (up i) (up (i - 3))) done

(* The PNG image data: the filtered scanlines, compressed in bands of
   [band_rows] rows (the bands filtered and compressed in parallel). *)
let image_data ?(par = sequential) w h data =
  let stride = (w * 3) + 1 in
  let out = Bytes.create (stride * h) in
  let nb = bands h in
  par nb (fun b ->
      for y = b * band_rows to min h ((b + 1) * band_rows) - 1 do
        filter_row w data out y
      done);
  deflate ~par ~cuts:(Array.init (nb - 1) (fun b -> (b + 1) * band_rows * stride)) (Bytes.unsafe_to_string out)

(* A tEXt keyword is 1-79 Latin-1 bytes without NUL; the text has no NUL. *)
let check_text (k, v) =
  if
    k = "" || String.length k > 79 || String.contains k '\000'
    || String.contains v '\000'
  then invalid_arg ("Png_codec.encode: invalid tEXt entry " ^ String.escaped k)

let encode ?par ?(text = []) w h data =
  List.iter check_text text;
  let idat = image_data ?par w h data in
  let b = Buffer.create (String.length idat + 1024) in
  Buffer.add_string b signature;
  (* width, height, depth 8, colour type 2 (RGB), deflate, filter method
     0, no interlace *)
  add_chunk b "IHDR" (be32 w ^ be32 h ^ "\008\002\000\000\000");
  List.iter (fun (k, v) -> add_chunk b "tEXt" (k ^ "\000" ^ v)) text;
  add_chunk b "IDAT" idat;
  add_chunk b "IEND" "";
  Buffer.contents b

(* {1 Reading} *)

(* The chunks (type, data) of the PNG [s] before IEND, CRCs checked. *)
let chunks s =
  let n = String.length s in
  if not (String.starts_with ~prefix:signature s) then
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

let chunk s typ = List.assoc_opt typ (chunks s)

let text s =
  List.filter_map
    (fun (typ, data) ->
      if typ <> "tEXt" then None
      else
        match String.index_opt data '\000' with
        | None -> Some (data, "")
        | Some i ->
            let n = String.length data in
            Some (String.sub data 0 i, String.sub data (i + 1) (n - i - 1)))
    (chunks s)

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
let check s =
  let chunks = chunks s in
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
