let block = 32
let gamma = 1. /. 2.5

let encode (c : Color.t) =
  let e x = Float.pow (Float.max 0. x) gamma in
  Color.make (e c.r) (e c.g) (e c.b)

let differs threshold (a : Color.t) (b : Color.t) =
  Float.abs (a.r -. b.r) +. Float.abs (a.g -. b.g) +. Float.abs (a.b -. b.b) >= threshold

let supersample ~depth sample x y (centre : Color.t) =
  let n = depth in
  let acc = ref centre in
  for j = 0 to n - 1 do
    for i = 0 to n - 1 do
      let dx = ((float_of_int i +. 0.5) /. float_of_int n) -. 0.5
      and dy = ((float_of_int j +. 0.5) /. float_of_int n) -. 0.5 in
      acc :=
        Color.add !acc (sample (float_of_int x +. 0.5 +. dx) (float_of_int y +. 0.5 +. dy))
    done
  done;
  Color.scale (1. /. float_of_int ((n * n) + 1)) !acc

(* One block: a (w+1) x (h+1) buffer whose row 0 and column 0 are the
   neighbours above and left of the block (outside the image at its
   border: still traced, as POV-Ray does). *)
let render_block ~threshold ~depth sample img (t : Render.tile) =
  let w = t.x1 - t.x0 and h = t.y1 - t.y0 in
  let bw = w + 1 in
  let value = Array.make (bw * (h + 1)) Color.black in
  let enc = Array.make (bw * (h + 1)) Color.black in
  let done_ = Array.make (bw * (h + 1)) false in
  let idx i j = (j * bw) + i in
  let trace i j =
    let x = t.x0 + i - 1 and y = t.y0 + j - 1 in
    let c = sample (float_of_int x +. 0.5) (float_of_int y +. 0.5) in
    let k = idx i j in
    value.(k) <- c;
    enc.(k) <- encode c
  in
  let super i j =
    let k = idx i j in
    if not done_.(k) then begin
      done_.(k) <- true;
      let c = supersample ~depth sample (t.x0 + i - 1) (t.y0 + j - 1) value.(k) in
      value.(k) <- c;
      enc.(k) <- encode c
    end
  in
  for i = 1 to w do trace i 0 done;
  for j = 1 to h do
    trace 0 j;
    for i = 1 to w do
      trace i j;
      let k = idx i j in
      let left = differs threshold enc.(idx (i - 1) j) enc.(k) in
      let up = differs threshold enc.(idx i (j - 1)) enc.(k) in
      if left then super (i - 1) j;
      if up then super i (j - 1);
      if left || up then super i j
    done
  done;
  for j = 1 to h do
    for i = 1 to w do
      let c = value.(idx i j) in
      Image.set img (t.x0 + i - 1) (t.y0 + j - 1) c.r c.g c.b
    done
  done

let render ~domains ?progress ?cancelled ~width ~height ~threshold ~depth sample =
  let img = Image.create width height in
  Render.run_tiles ~domains ?progress ?cancelled ~width ~height ~size:block
    (render_block ~threshold ~depth sample img);
  img
