type image = {
  w : int;
  h : int;
  px : Color.rgbft array;
  once : bool;
  interpolate : bool;
}

type t =
  | Solid of Color.rgbft
  | Map of { pattern : Pattern.t; entries : (float * t) array; xform : Transform.t }
  | Blocks of { pattern : Pattern.t; cells : t array; xform : Transform.t }
  | Image_map of { image : image; xform : Transform.t }

let solid c = Solid c
let black = Solid (Color.opaque Color.black)
let sc r g b = Solid (Color.rgbft r g b 0. 0.)

let default_entries (k : Pattern.kind) =
  match k with
  | Checker -> [| (0., sc 0. 0. 1.); (1., sc 0. 1. 0.) |]
  | Hexagon -> [| (0., sc 0. 0. 1.); (1., sc 0. 1. 0.); (2., sc 1. 0. 0.) |]
  | Brick _ -> [| (0., sc 0.5 0.5 0.5); (1., sc 0.6 0.15 0.15) |]
  | Bozo ->
      [| (0.4, sc 1. 1. 1.); (0.4, sc 0. 1. 0.); (0.6, sc 0. 1. 0.); (0.6, sc 0. 0. 1.);
         (0.8, sc 0. 0. 1.); (0.8, sc 1. 0. 0.) |]
  | Radial -> [| (0., sc 0. 1. 1.); (1. /. 3., sc 1. 1. 0.); (2. /. 3., sc 1. 0. 1.); (1., sc 0. 1. 1.) |]
  | Marble -> [| (0., sc 0.9 0.8 0.8); (0.9, sc 0.9 0.08 0.08); (0.9, sc 0. 0. 0.) |]
  | Wood -> [| (0.6, sc 0.666 0.312 0.2); (0.6, sc 0.4 0.1333 0.0666) |]
  | Agate _ ->
      [| (0., sc 1. 1. 1.); (0.5, sc 0.95 0.75 0.5); (0.5, sc 0.9 0.7 0.5); (0.6, sc 0.9 0.7 0.4);
         (0.6, sc 1. 0.7 0.4); (1., sc 0.6 0.3 0.) |]
  | _ -> [| (0., sc 0. 0. 0.); (1., sc 1. 1. 1.) |]

let rec transform t p =
  match p with
  | Solid _ -> p
  | Map m ->
      Map
        {
          m with
          xform = Transform.then_ m.xform t;
          entries = Array.map (fun (v, q) -> (v, transform t q)) m.entries;
        }
  | Blocks b ->
      Blocks { b with xform = Transform.then_ b.xform t; cells = Array.map (transform t) b.cells }
  | Image_map i -> Image_map { i with xform = Transform.then_ i.xform t }

let lerp (a : Color.rgbft) (b : Color.rgbft) k =
  let l x y = x +. (k *. (y -. x)) in
  {
    Color.c = Color.make (l a.c.r b.c.r) (l a.c.g b.c.g) (l a.c.b b.c.b);
    filter = l a.filter b.filter;
    transmit = l a.transmit b.transmit;
  }

let clear = Color.rgbft 0. 0. 0. 0. 1.

let image_eval (im : image) (p : Vec3.t) =
  let u = p.x and v = p.y in
  if im.once && (u < 0. || u >= 1. || v < 0. || v >= 1.) then clear
  else
    let u = u -. Float.floor u and v = v -. Float.floor v in
    let fx = u *. float_of_int im.w and fy = (1. -. v) *. float_of_int im.h in
    let get i j =
      let i = ((i mod im.w) + im.w) mod im.w and j = ((j mod im.h) + im.h) mod im.h in
      im.px.((j * im.w) + i)
    in
    if not im.interpolate then get (int_of_float fx) (int_of_float fy)
    else
      let x = fx -. 0.5 and y = fy -. 0.5 in
      let i = int_of_float (Float.floor x) and j = int_of_float (Float.floor y) in
      let a = x -. Float.floor x and b = y -. Float.floor y in
      lerp (lerp (get i j) (get (i + 1) j) a) (lerp (get i (j + 1)) (get (i + 1) (j + 1)) a) b

(* Whether every point is opaque (filter and transmit 0): a shadow ray
   through such a pigment is blocked without evaluating it (asked at
   every shadow ray's crossing: no closure made for the walk). *)
let rec opaque = function
  | Solid c -> c.filter = 0. && c.transmit = 0.
  | Map { entries; _ } -> entries_opaque entries 0
  | Blocks { cells; _ } -> cells_opaque cells 0
  | Image_map _ -> false

and entries_opaque a i = i >= Array.length a || (opaque (snd (Array.unsafe_get a i)) && entries_opaque a (i + 1))
and cells_opaque a i = i >= Array.length a || (opaque (Array.unsafe_get a i) && cells_opaque a (i + 1))

let rec eval p point =
  match p with
  | Solid c -> c
  | Map { pattern; entries; xform } ->
      let v = Pattern.value pattern (Transform.inv_point xform point) in
      let n = Array.length entries in
      if n = 0 then Color.opaque Color.black
      else
        let v0, p0 = entries.(0) in
        if v <= v0 then eval p0 point
        else begin
          (* the first entry above v (a loop: no closure per point) *)
          let i = ref 1 in
          while !i < n && not (v < fst entries.(!i)) do
            incr i
          done;
          if !i >= n then eval (snd entries.(n - 1)) point
          else
            let vi, pi = entries.(!i) and vp, pp = entries.(!i - 1) in
            if vi -. vp <= 0. then eval pi point
            else lerp (eval pp point) (eval pi point) ((v -. vp) /. (vi -. vp))
        end
  | Blocks { pattern; cells; xform } ->
      let i = int_of_float (Pattern.value pattern (Transform.inv_point xform point)) in
      let n = Array.length cells in
      if n = 0 then Color.opaque Color.black else eval cells.(Int.min (n - 1) (Int.max 0 i)) point
  | Image_map { image; xform } -> image_eval image (Transform.inv_point xform point)

(* a solid colour, or a plain checker of them, without making the point
   a vector *)
let rec eval_m p (point : Vec3.m) =
  match p with
  | Solid c -> c
  | Blocks { pattern = { kind = Pattern.Checker; turbulence = None; _ }; cells; xform }
    when Transform.is_identity xform && Array.length cells > 0 ->
      let n = Array.length cells in
      eval_m cells.(Int.min (n - 1) (Pattern.checker_m point)) point
  | _ -> eval p (Vec3.of_m point)
