(* How far apart two 8-bit images are (see metrics.mli). *)

open Image

let same_size fn (a : rgb8) (b : rgb8) =
  Image.check_rgb8 fn a;
  Image.check_rgb8 fn b;
  if a.w <> b.w || a.h <> b.h then
    invalid_arg
      (Printf.sprintf "%s: sizes differ (%dx%d vs %dx%d)" fn a.w a.h b.w b.h)

let psnr a b =
  same_size "Metrics.psnr" a b;
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
  same_size "Metrics.ssim" a b;
  if a.w < 11 || a.h < 11 then invalid_arg "Metrics.ssim: smaller than 11x11";
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
  same_size "Metrics.max_diff" a b;
  let m = ref 0 in
  Bytes.iteri
    (fun i c -> m := max !m (abs (Char.code c - Bytes.get_uint8 b.data i)))
    a.data;
  !m

let diff_image ?(gain = 4) a b =
  same_size "Metrics.diff_image" a b;
  if gain < 0 then invalid_arg "Metrics.diff_image: negative gain";
  let scaled i c =
    Char.chr (min 255 (gain * abs (Char.code c - Bytes.get_uint8 b.data i)))
  in
  { a with data = Bytes.mapi scaled a.data }

let side_by_side = function
  | [] -> invalid_arg "Metrics.side_by_side: no images"
  | ims ->
      List.iter (check_rgb8 "Metrics.side_by_side") ims;
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
