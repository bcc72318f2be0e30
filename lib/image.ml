(* Skeleton: the frame buffer and PPM writer only; the rest is being built. *)
type t = { w : int; h : int; px : Float.Array.t }

let create w h =
  if w <= 0 || h <= 0 then invalid_arg "Image.create";
  { w; h; px = Float.Array.make (w * h * 3) 0. }

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
type encoding = Srgb | Identity

let srgb_encode c =
  if c <= 0.0031308 then 12.92 *. c
  else (1.055 *. Float.pow c (1. /. 2.4)) -. 0.055

let to_rgb8 enc (img : t) =
  let data = Bytes.create (img.w * img.h * 3) in
  Float.Array.iteri
    (fun i v ->
      let v = if Float.is_nan v then 0. else Float.min 1. (Float.max 0. v) in
      let v = match enc with Srgb -> srgb_encode v | Identity -> v in
      Bytes.set data i (Char.chr (int_of_float (Float.round (v *. 255.)))))
    img.px;
  { w = img.w; h = img.h; data }

let write_atomic path f =
  let tmp = Filename.temp_file ~temp_dir:(Filename.dirname path) ".camlray" ".tmp" in
  match
    let oc = open_out_bin tmp in
    Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> f oc; flush oc)
  with
  | () -> Sys.rename tmp path
  | exception e -> (try Sys.remove tmp with _ -> ()); raise e

let write_ppm path (im : rgb8) =
  write_atomic path (fun oc ->
      Printf.fprintf oc "P6\n%d %d\n255\n" im.w im.h;
      output_bytes oc im.data)

let write_png ?text:_ path im = write_ppm path im
let write_pfm _ _ = failwith "PFM output is not implemented yet"
let read _ = failwith "Image.read is not implemented yet"
let png_text _ = []
let psnr _ _ = nan
let ssim _ _ = nan
let max_diff _ _ = 0
let diff_image ?gain:_ a _ = a
let side_by_side l = List.hd l
