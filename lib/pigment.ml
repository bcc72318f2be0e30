type image = {
  w : int;
  h : int;
  px : Color.rgbft array;
  once : bool;
  interpolate : int;
  map_type : int;
}

type t =
  | Solid of Color.rgbft
  | Map of { pattern : Pattern.t; entries : (float * t) array; xform : Transform.t }
  | Blocks of { pattern : Pattern.t; cells : t array; xform : Transform.t }
  | Image_map of { image : image; xform : Transform.t; warp : Pattern.t option }
  | Average of { entries : (float * t) array; xform : Transform.t; warp : Pattern.t option }
  | Uv of t

let solid c = Solid c
let black = Solid (Color.opaque Color.black)
let sc r g b = Solid (Color.rgbft r g b 0. 0.)

let default_entries (k : Pattern.kind) =
  match k with
  | Checker | Object _ -> [| (0., sc 0. 0. 1.); (1., sc 0. 1. 0.) |]
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
  (* only for exponent 2: POV-Ray gives its other mandels, and julia, the
     grey map *)
  | Mandel { exponent = 2; _ } ->
      [| (0.001, sc 0. 0. 0.); (0.001, sc 0. 1. 1.); (0.012, sc 1. 1. 0.); (0.015, sc 1. 0. 1.);
         (0.1, sc 0. 1. 1.) |]
  | _ -> [| (0., sc 0. 0. 0.); (1., sc 1. 1. 1.) |]

let transform t p =
  match p with
  | Solid _ -> p
  (* POV-Ray 3.7 (pattern.cpp's Transform_Tpattern): only the map's own
     pattern moves; its entries are taken at the point the pattern is
     evaluated at, so they follow it *)
  | Map m -> Map { m with xform = Transform.then_ m.xform t }
  | Blocks b -> Blocks { b with xform = Transform.then_ b.xform t }
  | Image_map i -> Image_map { i with xform = Transform.then_ i.xform t }
  | Average a -> Average { a with xform = Transform.then_ a.xform t }
  (* POV-Ray: transformations written after a uv-mapped pigment (the
     texture's, the object's) leave it as it is (measured) *)
  | Uv _ -> p

let uv = function Uv _ as p -> p | p -> Uv p

let rec uses_uv = function
  | Uv _ -> true
  | Solid _ | Image_map _ -> false
  | Map { entries = es; _ } | Average { entries = es; _ } -> Array.exists (fun (_, q) -> uses_uv q) es
  | Blocks { cells; _ } -> Array.exists uses_uv cells

let clear = Color.rgbft 0. 0. 0. 0. 1.

type out = {
  mutable r : float;
  mutable g : float;
  mutable b : float;
  mutable filter : float;
  mutable transmit : float;
}

let out () = { r = 0.; g = 0.; b = 0.; filter = 0.; transmit = 0. }

let[@inline] set (o : out) (c : Color.rgbft) =
  o.r <- c.c.r;
  o.g <- c.c.g;
  o.b <- c.c.b;
  o.filter <- c.filter;
  o.transmit <- c.transmit

let to_rgbft (o : out) = Color.rgbft o.r o.g o.b o.filter o.transmit

let[@inline] lerp1 k x y = x +. (k *. (y -. x))

(* o := lerp o t k, channel by channel *)
let[@inline] lerp_into (o : out) (t : out) k =
  o.r <- lerp1 k o.r t.r;
  o.g <- lerp1 k o.g t.g;
  o.b <- lerp1 k o.b t.b;
  o.filter <- lerp1 k o.filter t.filter;
  o.transmit <- lerp1 k o.transmit t.transmit

let pixel (im : image) i j =
  let i = ((i mod im.w) + im.w) mod im.w and j = ((j mod im.h) + im.h) mod im.h in
  im.px.((j * im.w) + i)

(* a corner for normalized-distance and bicubic interpolation, as POV-Ray
   fetches it: repeated images wrap, a [once] image gives its edge *)
let corner (im : image) i j =
  if im.once then im.px.((Int.max 0 (Int.min (im.h - 1) j) * im.w) + Int.max 0 (Int.min (im.w - 1) i))
  else pixel im i j

(* o += k c, channel by channel *)
let[@inline] add_scaled (o : out) k (c : Color.rgbft) =
  o.r <- o.r +. (k *. c.c.r);
  o.g <- o.g +. (k *. c.c.g);
  o.b <- o.b +. (k *. c.c.b);
  o.filter <- o.filter +. (k *. c.filter);
  o.transmit <- o.transmit +. (k *. c.transmit)

let zero (o : out) =
  o.r <- 0.;
  o.g <- 0.;
  o.b <- 0.;
  o.filter <- 0.;
  o.transmit <- 0.

(* POV-Ray's cubic weights (imageutil.cpp) of the four texels around, for
   the fraction [p] of the coordinate *)
let[@inline] cubic_weight p k =
  let q = 1. -. p in
  if k = 0 then -0.5 *. p *. q *. q
  else if k = 1 then 0.5 *. q *. ((q *. ((3. *. p) +. 1.)) +. 1.)
  else if k = 2 then 0.5 *. p *. ((p *. ((3. *. q) +. 1.)) +. 1.)
  else -0.5 *. q *. p *. p

(* interpolate 4: the four texels around (the one at [ix, iy], left, up,
   up-left), each by the inverse square of its distance, normalised, as
   a bump map's ({!Bump_map.weight}) *)
let norm_dist_into (im : image) fx fy (o : out) =
  let x = fx +. 0.5 and y = fy +. 0.5 in
  let ix = int_of_float x and iy = int_of_float y in
  let p = x -. float_of_int ix and q = y -. float_of_int iy in
  zero o;
  add_scaled o (Bump_map.weight 4 p q 0) (corner im ix iy);
  add_scaled o (Bump_map.weight 4 p q 1) (corner im (ix - 1) iy);
  add_scaled o (Bump_map.weight 4 p q 2) (corner im ix (iy - 1));
  add_scaled o (Bump_map.weight 4 p q 3) (corner im (ix - 1) (iy - 1))

(* interpolate 3: the 4 x 4 texels around, by cubic weights along each
   axis *)
let bicubic_into (im : image) fx fy (o : out) =
  let x = fx +. 0.5 and y = fy +. 0.5 in
  let ix = int_of_float x and iy = int_of_float y in
  let p = x -. float_of_int ix and q = y -. float_of_int iy in
  zero o;
  for i = 0 to 3 do
    for j = 0 to 3 do
      add_scaled o (cubic_weight p i *. cubic_weight q j) (corner im (ix + i - 2) (iy + j - 2))
    done
  done

(* the image at [p] (in its own space) into [o]; interpolated: the lerp of
   two lerps, as [lerp] makes it, channel by channel (no tuple or closure:
   the floats stay unboxed) *)
(* the point's place on the image, per domain *)
let coords_key = Scratch.key Vec3.m

(* POV-Ray's map_pos ({!Bump_map.locate}): column and row from the top,
   with its tiny offset, so that a point on a row's edge takes the row
   POV-Ray takes (the row above, by (1 - v) h, every fifth row of a
   120-row image seen at one pixel per 0.01) *)
let image_into (im : image) (p : Vec3.m) (o : out) =
  let c = Scratch.get coords_key in
  if not (Bump_map.locate ~w:im.w ~h:im.h ~once:im.once ~map_type:im.map_type p c) then set o clear
  else
    let fx = c.mx and fy = c.my in
    if im.interpolate = 0 then set o (pixel im (int_of_float fx) (int_of_float fy))
    else if im.interpolate = 4 then norm_dist_into im fx fy o
    else if im.interpolate = 3 then bicubic_into im fx fy o
    else begin
      let x = fx -. 0.5 and y = fy -. 0.5 in
      let i = int_of_float (Float.floor x) and j = int_of_float (Float.floor y) in
      let a = x -. Float.floor x and b = y -. Float.floor y in
      let p00 = pixel im i j and p10 = pixel im (i + 1) j in
      let p01 = pixel im i (j + 1) and p11 = pixel im (i + 1) (j + 1) in
      o.r <- lerp1 b (lerp1 a p00.c.r p10.c.r) (lerp1 a p01.c.r p11.c.r);
      o.g <- lerp1 b (lerp1 a p00.c.g p10.c.g) (lerp1 a p01.c.g p11.c.g);
      o.b <- lerp1 b (lerp1 a p00.c.b p10.c.b) (lerp1 a p01.c.b p11.c.b);
      o.filter <- lerp1 b (lerp1 a p00.filter p10.filter) (lerp1 a p01.filter p11.filter);
      o.transmit <- lerp1 b (lerp1 a p00.transmit p10.transmit) (lerp1 a p01.transmit p11.transmit)
    end

(* Whether every point is opaque (filter and transmit 0): a shadow ray
   through such a pigment is blocked without evaluating it (asked at
   every shadow ray's crossing: no closure made for the walk). *)
let rec opaque = function
  | Solid c -> c.filter = 0. && c.transmit = 0.
  | Map { entries; _ } -> entries_opaque entries 0
  | Blocks { cells; _ } -> cells_opaque cells 0
  | Image_map _ -> false
  | Average { entries; _ } -> entries_opaque entries 0
  | Uv p -> opaque p

and entries_opaque a i = i >= Array.length a || (opaque (snd (Array.unsafe_get a i)) && entries_opaque a (i + 1))
and cells_opaque a i = i >= Array.length a || (opaque (Array.unsafe_get a i) && cells_opaque a (i + 1))

(* the largest |channel| anywhere: a map's or a block pattern's entries
   bound it (a map interpolates between neighbours and holds its ends
   past them), an image its pixels, an average its weighted entries *)
let rec bound = function
  | Solid c -> Float.max (Float.abs c.c.r) (Float.max (Float.abs c.c.g) (Float.abs c.c.b))
  | Map { entries; _ } -> Array.fold_left (fun m (_, p) -> Float.max m (bound p)) 0. entries
  | Blocks { cells; _ } -> Array.fold_left (fun m p -> Float.max m (bound p)) 0. cells
  | Image_map { image; _ } ->
      Array.fold_left (fun m (c : Color.rgbft) -> Float.max m (bound (Solid c))) 0. image.px
  | Average { entries; _ } -> Array.fold_left (fun m (w, p) -> m +. (Float.abs w *. bound p)) 0. entries
  | Uv p -> bound p

(* Per domain: the point in an image's space, the pattern's work, per
   nesting depth a colour for the second of two entries blended, and the
   first depth no running evaluation holds (a pigment function in a
   pattern evaluates a pigment inside another's evaluation: it starts
   there). *)
type work = {
  q : Vec3.m;
  pw : Pattern.work;
  tmp : out Scratch.levels;
  pts : Vec3.m Scratch.levels;  (* per depth: the point a map's entries are taken at *)
  mutable used : int;
}

let work_key =
  Scratch.key (fun () ->
      { q = Vec3.m (); pw = Pattern.work (); tmp = Scratch.levels out; pts = Scratch.levels Vec3.m; used = 0 })

(* The pattern of a map at [point] (taken into its space by [xform]'s
   inverse), and the point its entries are evaluated at (POV-Ray 3.7's
   Compute_Pigment: the pattern's own point, its transformations, warps
   and turbulence applied) kept at depth [d], read with [entries_at]: the
   entries' evaluations use deeper levels only. Kept before the raw
   pattern is evaluated: a function pattern's pigments are evaluated
   with this domain's work too (at depths from [w.used] on). Inlined:
   the value is not boxed. *)
let[@inline] eval_keeping w pattern xform (point : Vec3.m) d =
  let pw = w.pw in
  Transform.inv_point_m xform point pw.p;
  Pattern.warped_m pattern pw.p pw;
  let e = Scratch.level w.pts d in
  if w.used <= d then w.used <- d + 1;
  let p = Pattern.entries_point pattern pw in
  Vec3.set e p.mx p.my p.mz;
  Pattern.eval_warped pattern pw;
  pw.r.v

let[@inline] entries_at w d = Scratch.level w.pts d

(* The commonest pattern, a checker of the pattern space itself, read
   without the pattern's work: the cell at [point] (any other pigment is
   itself) *)
let[@inline] checker_cell p point =
  match p with
  | Blocks { pattern = { kind = Pattern.Checker; turbulence = None; warps = [||]; _ }; cells; xform }
    when Transform.is_identity xform && Array.length cells > 0 ->
      cells.(Int.min (Array.length cells - 1) (Pattern.checker_m point))
  | _ -> p

let rec into_d w p (point : Vec3.m) (o : out) d =
  match checker_cell p point with
  | Solid c -> set o c
  | Map { pattern; entries; xform } ->
      let v = eval_keeping w pattern xform point d in
      let n = Array.length entries in
      if n = 0 then set o (Color.opaque Color.black)
      else begin
        let e = entries_at w d in
        let i = Pattern.around entries v in
        if i = 0 then into_d w (snd entries.(0)) e o (d + 1)
        else if i >= n then into_d w (snd entries.(n - 1)) e o (d + 1)
        else
          let vi, pi = entries.(i) and vp, pp = entries.(i - 1) in
          if vi -. vp <= 0. then into_d w pi e o (d + 1)
          else begin
            let k = (v -. vp) /. (vi -. vp) in
            let t = Scratch.level w.tmp d in
            into_d w pp e o (d + 1);
            into_d w pi e t (d + 1);
            lerp_into o t k
          end
      end
  | Blocks { pattern; cells; xform } ->
      let i = int_of_float (eval_keeping w pattern xform point d) in
      let n = Array.length cells in
      if n = 0 then set o (Color.opaque Color.black)
      else into_d w cells.(Int.min (n - 1) (Int.max 0 i)) (entries_at w d) o (d + 1)
  | Image_map { image; xform; warp = None } ->
      Transform.inv_point_m xform point w.q;
      image_into image w.q o
  | Image_map { image; xform; warp = Some pattern } ->
      Transform.inv_point_m xform point w.q;
      Pattern.warped_m pattern w.q w.pw;
      image_into image w.pw.p o
  | Average { entries = es; xform; warp } ->
      let t = Scratch.level w.tmp d and e = Scratch.level w.pts d in
      if w.used <= d then w.used <- d + 1;
      Transform.inv_point_m xform point e;
      (match warp with Some pattern -> Pattern.warp_in_place pattern e w.pw | None -> ());
      o.r <- 0.;
      o.g <- 0.;
      o.b <- 0.;
      o.filter <- 0.;
      o.transmit <- 0.;
      for i = 0 to Array.length es - 1 do
        let k, q = Array.unsafe_get es i in
        into_d w q e t (d + 1);
        o.r <- o.r +. (k *. t.r);
        o.g <- o.g +. (k *. t.g);
        o.b <- o.b +. (k *. t.b);
        o.filter <- o.filter +. (k *. t.filter);
        o.transmit <- o.transmit +. (k *. t.transmit)
      done
  | Uv q -> into_d w q (Pattern.uv_point ()) o d

(* a solid colour, or a plain checker of solid colours, without the
   domain's work *)
let into p point o =
  match checker_cell p point with
  | Solid c -> set o c
  | q ->
      let w = Scratch.get work_key in
      let base = w.used in
      into_d w q point o base;
      w.used <- base

let eval p point =
  match p with
  | Solid c -> c
  | _ ->
      let o = out () and q = Vec3.m () in
      Vec3.load q point;
      into p q o;
      to_rgbft o
