let block = 32
let gamma = 1. /. 2.5

let[@inline] encode1 x = Float.pow (Float.max 0. x) gamma
let encode (c : Color.t) = Color.make (encode1 c.r) (encode1 c.g) (encode1 c.b)

let[@inline] differs3 threshold ar ag ab br bg bb =
  Float.abs (ar -. br) +. Float.abs (ag -. bg) +. Float.abs (ab -. bb) >= threshold

let differs threshold (a : Color.t) (b : Color.t) = differs3 threshold a.r a.g a.b b.r b.g b.b

(* The n x n samples added to the centre's [(cr, cg, cb)], channel by
   channel in this order, into [out] at [3k]; [c] takes each sample. *)
let supersample_into ~depth sample (c : Color.acc) x y cr cg cb out k =
  let n = depth in
  let r = ref cr and g = ref cg and b = ref cb in
  for j = 0 to n - 1 do
    for i = 0 to n - 1 do
      let dx = ((float_of_int i +. 0.5) /. float_of_int n) -. 0.5
      and dy = ((float_of_int j +. 0.5) /. float_of_int n) -. 0.5 in
      sample (float_of_int x +. 0.5 +. dx) (float_of_int y +. 0.5 +. dy) c;
      r := !r +. c.ar;
      g := !g +. c.ag;
      b := !b +. c.ab
    done
  done;
  let s = 1. /. float_of_int ((n * n) + 1) in
  Float.Array.unsafe_set out (3 * k) (s *. !r);
  Float.Array.unsafe_set out ((3 * k) + 1) (s *. !g);
  Float.Array.unsafe_set out ((3 * k) + 2) (s *. !b)

(* a sample function returning colours, as one writing them *)
let writing sample px py (out : Color.acc) =
  let (c : Color.t) = sample px py in
  Color.acc_set out c.r c.g c.b

let supersample ~depth sample x y (centre : Color.t) =
  let out = Float.Array.create 3 in
  supersample_into ~depth (writing sample) (Color.acc 0.) x y centre.r centre.g centre.b out 0;
  Color.make (Float.Array.get out 0) (Float.Array.get out 1) (Float.Array.get out 2)

(* One block's samples, per domain, flat: colours stored in an array of
   records would be promoted by every minor collection that finds the
   block half done (the arrays, too large for the minor heap, live in
   the major one), and the major collector would mark and sweep them. *)
type buffers = { value : Float.Array.t; enc : Float.Array.t; done_ : Bytes.t; one : Color.acc }

let cells = (block + 1) * (block + 1)

let buffers_key =
  Scratch.key (fun () ->
      { value = Float.Array.create (3 * cells); enc = Float.Array.create (3 * cells); done_ = Bytes.create cells;
        one = Color.acc 0. })

let[@inline] get a k c = Float.Array.unsafe_get a ((3 * k) + c)

let set_encoded b k =
  Float.Array.unsafe_set b.enc (3 * k) (encode1 (get b.value k 0));
  Float.Array.unsafe_set b.enc ((3 * k) + 1) (encode1 (get b.value k 1));
  Float.Array.unsafe_set b.enc ((3 * k) + 2) (encode1 (get b.value k 2))

(* The block's cell (i, j) is pixel (x0 + i - 1, y0 + j - 1), at [k]. The
   steps are functions of their own, not closures made per block: a
   minor collection in the middle of a block would promote those. *)
let trace_cell b sample (t : Render.tile) bw i j =
  let x = t.x0 + i - 1 and y = t.y0 + j - 1 in
  let one = b.one in
  sample (float_of_int x +. 0.5) (float_of_int y +. 0.5) one;
  let k = (j * bw) + i in
  Float.Array.unsafe_set b.value (3 * k) one.ar;
  Float.Array.unsafe_set b.value ((3 * k) + 1) one.ag;
  Float.Array.unsafe_set b.value ((3 * k) + 2) one.ab;
  set_encoded b k

let super_cell b ~depth sample (t : Render.tile) bw i j =
  let k = (j * bw) + i in
  if Bytes.unsafe_get b.done_ k = '\000' then begin
    Bytes.unsafe_set b.done_ k '\001';
    let v = b.value in
    supersample_into ~depth sample b.one (t.x0 + i - 1) (t.y0 + j - 1) (get v k 0) (get v k 1) (get v k 2) v k;
    set_encoded b k
  end

let[@inline] differ threshold b k k' =
  let e = b.enc in
  differs3 threshold (get e k 0) (get e k 1) (get e k 2) (get e k' 0) (get e k' 1) (get e k' 2)

(* One block: a (w+1) x (h+1) buffer whose row 0 and column 0 are the
   neighbours above and left of the block (outside the image at its
   border: still traced, as POV-Ray does). *)
let render_block ~threshold ~depth sample img (t : Render.tile) =
  let w = t.x1 - t.x0 and h = t.y1 - t.y0 in
  let bw = w + 1 in
  let b = Scratch.get buffers_key in
  Bytes.fill b.done_ 0 (bw * (h + 1)) '\000';
  for i = 1 to w do trace_cell b sample t bw i 0 done;
  for j = 1 to h do
    trace_cell b sample t bw 0 j;
    for i = 1 to w do
      trace_cell b sample t bw i j;
      let k = (j * bw) + i in
      let left = differ threshold b (k - 1) k in
      let up = differ threshold b (k - bw) k in
      if left then super_cell b ~depth sample t bw (i - 1) j;
      if up then super_cell b ~depth sample t bw i (j - 1);
      if left || up then super_cell b ~depth sample t bw i j
    done
  done;
  let v = b.value in
  for j = 1 to h do
    for i = 1 to w do
      let k = (j * bw) + i in
      Image.set img (t.x0 + i - 1) (t.y0 + j - 1) (get v k 0) (get v k 1) (get v k 2)
    done
  done

let render_into ~domains ?progress ?cancelled ~width ~height ~threshold ~depth sample =
  let img = Image.create width height in
  Render.run_tiles ~domains ?progress ?cancelled ~width ~height ~size:block
    (render_block ~threshold ~depth sample img);
  img

let render ~domains ?progress ?cancelled ~width ~height ~threshold ~depth sample =
  render_into ~domains ?progress ?cancelled ~width ~height ~threshold ~depth (writing sample)
