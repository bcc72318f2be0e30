(* Height field values from image files and functions, by POV-Ray 3.7's
   image_height_at (imageutil.cpp) and its Image classes' float and
   16-bit conversions, reproduced in single precision. *)

let f32 = Floats.single

(* C's (HF_VAL) / (unsigned short) of a float: truncation, then the low
   16 bits (x86's conversion through a 32-bit integer) *)
let to_u16 x =
  if Float.is_nan x || Float.abs x >= 2147483648. then 0 else truncate x land 0xFFFF

let of_gray8 v = to_u16 (f32 (f32 (float v /. 255.) *. 65535.))
let of_gray16 v = to_u16 (f32 (f32 (float v /. 65535.) *. 65535.))
let of_index i = i * 256

(* 8-bit colour: red the high byte, green the low one *)
let of_rgb8 r g = to_u16 (((f32 (float r /. 255.) *. 256.) +. f32 (float g /. 255.)) *. 255.)

(* deeper colour: the grey (0.297, 0.589, 0.114) of the channels *)
let of_rgb16 r g b =
  let c v = f32 (float v /. 65535.) in
  let gray = f32 ((0.297 *. c r) +. (0.589 *. c g) +. (0.114 *. c b)) in
  to_u16 (f32 (gray *. 65535.))

(* a Gray_Int16 pixel set from a float (no clipping), read back *)
let of_float v = of_gray16 (to_u16 (f32 (f32 v *. 65535.)))

let of_color r g b =
  let q v = to_u16 (f32 (f32 v *. 65535.)) in
  of_rgb16 (q r) (q g) (q b)

type image = { w : int; h : int; v : int array  (** row 0 the top row *) }

(* {2 PNG} *)

let be32 s i = (Char.code s.[i] lsl 24) lor (Char.code s.[i + 1] lsl 16) lor (Char.code s.[i + 2] lsl 8) lor Char.code s.[i + 3]

let inflate data =
  let out = Buffer.create (4 * String.length data) and pos = ref 0 in
  Zlib.uncompress ~header:true
    (fun buf ->
      let n = Int.min (Bytes.length buf) (String.length data - !pos) in
      Bytes.blit_string data !pos buf 0 n;
      pos := !pos + n;
      n)
    (fun buf n -> Buffer.add_subbytes out buf 0 n);
  Buffer.contents out

let png s =
  let n = String.length s in
  let rec chunks i ihdr idat =
    if i + 8 > n then failwith "truncated PNG"
    else
      let len = be32 s i and kind = String.sub s (i + 4) 4 in
      if len < 0 || i + 12 + len > n then failwith "truncated PNG chunk";
      let body = String.sub s (i + 8) len in
      match kind with
      | "IHDR" -> chunks (i + 12 + len) (Some body) idat
      | "IDAT" -> chunks (i + 12 + len) ihdr (body :: idat)
      | "IEND" -> (ihdr, List.rev idat)
      | _ -> chunks (i + 12 + len) ihdr idat
  in
  match chunks 8 None [] with
  | None, _ -> failwith "PNG without IHDR"
  | Some hd, idat ->
      if String.length hd < 13 then failwith "bad IHDR";
      let w = be32 hd 0 and h = be32 hd 4 and depth = Char.code hd.[8] and ct = Char.code hd.[9] in
      if Char.code hd.[12] <> 0 then failwith "interlaced PNG height fields are not supported";
      if w <= 0 || h <= 0 || w * h > 1 lsl 26 then failwith "bad or too large PNG size";
      let channels = match ct with 0 -> 1 | 2 -> 3 | 3 -> 1 | 4 -> 2 | 6 -> 4 | _ -> failwith "bad PNG colour type" in
      let raw = try inflate (String.concat "" idat) with Zlib.Error (_, m) -> failwith ("bad PNG data: " ^ m) in
      let stride = ((w * channels * depth) + 7) / 8 and bpp = Int.max 1 (channels * depth / 8) in
      if String.length raw < h * (stride + 1) then failwith "truncated PNG data";
      let cur = Bytes.make stride '\000' and prev = Bytes.make stride '\000' in
      let v = Array.make (w * h) 0 in
      for y = 0 to h - 1 do
        let base = y * (stride + 1) in
        let filter = Char.code raw.[base] in
        for i = 0 to stride - 1 do
          let x = Char.code raw.[base + 1 + i] in
          let a = if i >= bpp then Char.code (Bytes.get cur (i - bpp)) else 0 in
          let b = Char.code (Bytes.get prev i) in
          let c = if i >= bpp then Char.code (Bytes.get prev (i - bpp)) else 0 in
          let p =
            match filter with
            | 0 -> x
            | 1 -> x + a
            | 2 -> x + b
            | 3 -> x + ((a + b) / 2)
            | 4 ->
                let p = a + b - c in
                let pa = abs (p - a) and pb = abs (p - b) and pc = abs (p - c) in
                x + if pa <= pb && pa <= pc then a else if pb <= pc then b else c
            | _ -> failwith "bad PNG filter"
          in
          Bytes.set cur i (Char.chr (p land 255))
        done;
        (* sample k of the row *)
        let sample k =
          match depth with
          | 16 -> (Char.code (Bytes.get cur (2 * k)) lsl 8) lor Char.code (Bytes.get cur ((2 * k) + 1))
          | 8 -> Char.code (Bytes.get cur k)
          | d ->
              let bit = k * d in
              (Char.code (Bytes.get cur (bit / 8)) lsr (8 - d - (bit mod 8))) land ((1 lsl d) - 1)
        in
        for x = 0 to w - 1 do
          let s k = sample ((x * channels) + k) in
          v.((y * w) + x) <-
            (match ct with
            | 3 -> of_index (s 0)
            | 0 | 4 ->
                if depth = 16 then of_gray16 (s 0)
                else if depth = 8 then of_gray8 (s 0)
                else of_gray8 (s 0 * 255 / ((1 lsl depth) - 1))
            | _ -> if depth = 16 then of_rgb16 (s 0) (s 1) (s 2) else of_rgb8 (s 0) (s 1))
        done;
        Bytes.blit cur 0 prev 0 stride
      done;
      { w; h; v }

(* {2 PGM and PPM (P2, P3, P5, P6)} *)

let pnm s =
  let w, h, channels, maxval, sample = Image.pnm s ~max_pixels:(1 lsl 26) in
  let count = w * h * channels in
  let raw = Array.init count sample in
  if Array.exists (fun x -> x > maxval) raw then failwith "sample exceeds maxval";
  (* other maxvals scaled to 8 or 16 bits *)
  let deep = maxval > 255 in
  let sc x = if maxval = 255 || maxval = 65535 then x else ((x * if deep then 65535 else 255) + (maxval / 2)) / maxval in
  let v =
    Array.init (w * h) (fun i ->
        if channels = 1 then if deep then of_gray16 (sc raw.(i)) else of_gray8 (sc raw.(i))
        else
          let c k = sc raw.((3 * i) + k) in
          if deep then of_rgb16 (c 0) (c 1) (c 2) else of_rgb8 (c 0) (c 1))
  in
  { w; h; v }

(* {2 JPEG} POV-Ray keeps a grey JPEG as 8-bit grey, a colour one as
   8-bit colour (red the high byte, green the low one) *)
let jpeg path s =
  let grey = Image.jpeg_components s = 1 in
  let img = Image.read_jpeg path in
  let b i = Char.code (Bytes.get img.data i) in
  let v = Array.init (img.w * img.h) (fun i -> if grey then of_gray8 (b (3 * i)) else of_rgb8 (b (3 * i)) (b ((3 * i) + 1))) in
  { w = img.w; h = img.h; v }

(* {2 GIF and POT} A GIF's heights are its palette indices (POV-Ray's
   8-bit indexed rule); a POT file (Fractint's continuous potential) is a
   GIF twice as wide as the field, the left half's index the high byte of
   a 16-bit height and the right half's the low byte *)
let gif ~pot path =
  let w, h, idx, _ = Image.gif_indices path in
  let b i = Char.code (Bytes.get idx i) in
  if pot then begin
    if w mod 2 <> 0 then failwith "a POT file's width must be even (two halves)";
    let hw = w / 2 in
    { w = hw; h; v = Array.init (hw * h) (fun i -> let x = i mod hw and y = i / hw in of_gray16 ((b ((y * w) + x) lsl 8) lor b ((y * w) + x + hw))) }
  end
  else { w; h; v = Array.init (w * h) (fun i -> of_index (b i)) }

let read ?(pot = false) path =
  let s = try In_channel.with_open_bin path In_channel.input_all with Sys_error m -> failwith m in
  let starts p = String.starts_with ~prefix:p s in
  if pot && not (Image.is_gif s) then failwith "a POT file is a GIF: this one is not"
  else if starts "\137PNG\r\n\026\n" then png s
  else if String.length s > 2 && s.[0] = 'P' && String.contains "2356" s.[1] then pnm s
  else if Image.is_jpeg s then jpeg path s
  else if Image.is_gif s then gif ~pot path
  else failwith "unknown image format (height fields read PNG, JPEG, GIF, POT, PGM and PPM)"
