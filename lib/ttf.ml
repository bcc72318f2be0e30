(* TrueType fonts (see ttf.mli). Every read is checked against the bytes'
   length: a damaged file fails with a message, never with an exception
   of its own. *)

type segment =
  | Line of float * float * float * float
  | Quad of float * float * float * float * float * float

type glyph = { contours : segment array array; xmin : float; ymin : float; xmax : float; ymax : float }

type t = {
  data : string;
  units_per_em : int;
  num_glyphs : int;
  loca : int array;  (* glyph i's data from loca.(i) to loca.(i + 1), in glyf *)
  glyf : int;
  metrics : (int * int) array;  (* advance width, left side bearing, per glyph *)
  cmap : int -> int;
  kern : (int * (int * int, int) Hashtbl.t) list;  (* horizontal tables: coverage, pairs *)
}

let fail fmt = Printf.ksprintf failwith fmt

let need d pos n what =
  if pos < 0 || pos + n > String.length d then fail "truncated %s (offset %d)" what pos

let u8 d p = need d p 1 "font data"; Char.code d.[p]
let u16 d p = need d p 2 "font data"; String.get_uint16_be d p
let s16 d p = need d p 2 "font data"; String.get_int16_be d p
let u32 d p = need d p 4 "font data"; Int32.to_int (String.get_int32_be d p) land 0xFFFFFFFF

let tables d =
  let n = u16 d 4 in
  List.init n (fun i ->
      let r = 12 + (16 * i) in
      need d r 16 "table directory";
      (String.sub d r 4, u32 d (r + 8)))

(* {2 Character maps} *)

let format0 d o c = if c >= 0 && c < 256 then u8 d (o + 6 + c) else 0

let format4 d o c =
  let segs = u16 d (o + 6) / 2 in
  let ends = o + 14 in
  let starts = ends + (2 * segs) + 2 in
  let deltas = starts + (2 * segs) and ranges = starts + (4 * segs) in
  let rec find i =
    if i >= segs then 0
    else if c > u16 d (ends + (2 * i)) then find (i + 1)
    else
      let start = u16 d (starts + (2 * i)) in
      if c < start then 0
      else
        let delta = u16 d (deltas + (2 * i)) and range = u16 d (ranges + (2 * i)) in
        if range = 0 then (c + delta) land 0xFFFF
        else
          let g = u16 d (ranges + (2 * i) + range + (2 * (c - start))) in
          if g = 0 then 0 else (g + delta) land 0xFFFF
  in
  find 0

let format6 d o c =
  let first = u16 d (o + 6) and count = u16 d (o + 8) in
  if c >= first && c < first + count then u16 d (o + 10 + (2 * (c - first))) else 0

let cmap d o =
  let n = u16 d (o + 2) in
  let subs = List.init n (fun i -> let r = o + 4 + (8 * i) in ((u16 d r, u16 d (r + 2)), o + u32 d (r + 4))) in
  let lookup so =
    match u16 d so with
    | 0 -> Some (format0 d so)
    | 4 -> Some (format4 d so)
    | 6 -> Some (format6 d so)
    | _ -> None
  in
  (* POV-Ray's order for ASCII text *)
  let prefs = [ (1, 0); (3, 1); (0, 3); (3, 0) ] in
  let chosen =
    List.find_map
      (fun p -> match List.assoc_opt p subs with Some so -> Option.map (fun f -> (p, f)) (lookup so) | None -> None)
      prefs
  in
  match chosen with
  | Some ((3, 0), f) -> fun c -> (match f c with 0 -> f (0xF000 + c) | g -> g)
  | Some (_, f) -> f
  | None -> fail "no character map camlray reads (formats 0, 4, 6)"

(* {2 Kerning} *)

let kern d o =
  let n = u16 d (o + 2) in
  let rec go i pos acc =
    if i >= n then List.rev acc
    else
      let len = u16 d (pos + 2) and coverage = u16 d (pos + 4) in
      let acc =
        if coverage lsr 8 = 0 && coverage land 1 = 1 then begin
          let pairs = u16 d (pos + 6) in
          let h = Hashtbl.create pairs in
          for k = 0 to pairs - 1 do
            let r = pos + 14 + (6 * k) in
            Hashtbl.replace h (u16 d r, u16 d (r + 2)) (s16 d (r + 4))
          done;
          (coverage, h) :: acc
        end
        else acc
      in
      go (i + 1) (pos + len) acc
  in
  go 0 (o + 4) []

let kerning f l r =
  let kx = ref 0 and kmin = ref (-f.units_per_em) in
  List.iter
    (fun (coverage, pairs) ->
      match Hashtbl.find_opt pairs (l, r) with
      | None -> ()
      | Some v ->
          let minimum = coverage land 2 <> 0 and cross = coverage land 4 <> 0 and override = coverage land 8 <> 0 in
          if cross then ()
          else if minimum then kmin := v
          else if override then kx := v
          else kx := !kx + v)
    f.kern;
  max !kx !kmin

(* {2 Parsing} *)

let parse d =
  if String.length d < 12 then fail "not a TrueType font (too short)";
  let d = if String.sub d 0 4 = "ttcf" then String.sub d (u32 d 12) (String.length d - u32 d 12) else d in
  let ts = tables d in
  let table name = match List.assoc_opt name ts with Some o -> o | None -> fail "no '%s' table" name in
  let head = table "head" and maxp = table "maxp" and hhea = table "hhea" and hmtx = table "hmtx" in
  let units_per_em = u16 d (head + 18) and long_loca = s16 d (head + 50) = 1 in
  if units_per_em < 16 || units_per_em > 16384 then fail "unitsPerEm %d out of range" units_per_em;
  let num_glyphs = u16 d (maxp + 4) in
  let loca_o = table "loca" in
  let loca =
    Array.init (num_glyphs + 1) (fun i -> if long_loca then u32 d (loca_o + (4 * i)) else 2 * u16 d (loca_o + (2 * i)))
  in
  let n_metrics = u16 d (hhea + 34) in
  if n_metrics = 0 then fail "no horizontal metrics";
  let metrics =
    Array.init num_glyphs (fun g ->
        if g < n_metrics then (u16 d (hmtx + (4 * g)), s16 d (hmtx + (4 * g) + 2))
        else
          let aw = u16 d (hmtx + (4 * (n_metrics - 1))) in
          let p = hmtx + (4 * n_metrics) + (2 * (g - n_metrics)) in
          (aw, if p + 2 <= String.length d then s16 d p else 0))
  in
  {
    data = d;
    units_per_em;
    num_glyphs;
    loca;
    glyf = table "glyf";
    metrics;
    cmap = cmap d (table "cmap");
    kern = (match List.assoc_opt "kern" ts with Some o -> kern d o | None -> []);
  }

let read path =
  let d = try In_channel.with_open_bin path In_channel.input_all with Sys_error e -> failwith e in
  try parse d with Failure m -> fail "%s: %s" path m

let units_per_em f = f.units_per_em

let glyph_index f c =
  let g = try f.cmap c with Failure _ -> 0 in
  if g >= 0 && g < f.num_glyphs then g else 0

let metric f g = if g >= 0 && g < f.num_glyphs then f.metrics.(g) else (0, 0)
let advance f g = fst (metric f g)
let lsb f g = snd (metric f g)

(* The segments of a closed contour of points [(x, y, on_curve)]: off-curve
   points are quadratic controls, with an on-curve point implied midway
   between two in a row *)
let contour (pts : (float * float * bool) array) =
  let n = Array.length pts in
  if n < 2 then [||]
  else begin
    (* start on an on-curve point, or the midpoint of the first two *)
    let first_on = Array.find_index (fun (_, _, on) -> on) pts in
    let start, ring =
      match first_on with
      | Some i -> (let x, y, _ = pts.(i) in (x, y), Array.init n (fun k -> pts.((i + 1 + k) mod n)))
      | None ->
          let x0, y0, _ = pts.(0) and x1, y1, _ = pts.(1) in
          (((x0 +. x1) /. 2., (y0 +. y1) /. 2.), Array.init n (fun k -> pts.((1 + k) mod n)))
    in
    (* [ring] ends with the start point itself when it is on-curve *)
    let segs = ref [] in
    let cur = ref start and ctrl = ref None in
    Array.iter
      (fun (x, y, on) ->
        let cx, cy = !cur in
        match (on, !ctrl) with
        | true, None ->
            if (x, y) <> (cx, cy) then segs := Line (cx, cy, x, y) :: !segs;
            cur := (x, y)
        | true, Some (qx, qy) ->
            segs := Quad (cx, cy, qx, qy, x, y) :: !segs;
            cur := (x, y);
            ctrl := None
        | false, None -> ctrl := Some (x, y)
        | false, Some (qx, qy) ->
            let mx = (qx +. x) /. 2. and my = (qy +. y) /. 2. in
            segs := Quad (cx, cy, qx, qy, mx, my) :: !segs;
            cur := (mx, my);
            ctrl := Some (x, y))
      ring;
    (* close back to the start *)
    let cx, cy = !cur and sx, sy = start in
    (match !ctrl with
    | Some (qx, qy) -> segs := Quad (cx, cy, qx, qy, sx, sy) :: !segs
    | None -> if (cx, cy) <> (sx, sy) then segs := Line (cx, cy, sx, sy) :: !segs);
    Array.of_list (List.rev !segs)
  end

let transform (a, b, c, e, dx, dy) s =
  let p x y = ((a *. x) +. (c *. y) +. dx, (b *. x) +. (e *. y) +. dy) in
  match s with
  | Line (x0, y0, x1, y1) ->
      let x0, y0 = p x0 y0 and x1, y1 = p x1 y1 in
      Line (x0, y0, x1, y1)
  | Quad (x0, y0, qx, qy, x1, y1) ->
      let x0, y0 = p x0 y0 and qx, qy = p qx qy and x1, y1 = p x1 y1 in
      Quad (x0, y0, qx, qy, x1, y1)

let rec glyph_at f g depth =
  if depth > 8 then fail "composite glyphs nested too deeply";
  if g < 0 || g >= f.num_glyphs then fail "glyph %d out of range" g;
  let d = f.data and o = f.glyf + f.loca.(g) in
  if f.loca.(g + 1) <= f.loca.(g) then { contours = [||]; xmin = 0.; ymin = 0.; xmax = 0.; ymax = 0. }
  else begin
    let nc = s16 d o in
    let box k = float (s16 d (o + 2 + (2 * k))) in
    let xmin = box 0 and ymin = box 1 and xmax = box 2 and ymax = box 3 in
    let contours =
      if nc >= 0 then begin
        let ends = Array.init nc (fun i -> u16 d (o + 10 + (2 * i))) in
        let npts = if nc = 0 then 0 else ends.(nc - 1) + 1 in
        let p = ref (o + 10 + (2 * nc)) in
        let ilen = u16 d !p in
        p := !p + 2 + ilen;
        let flags = Array.make npts 0 in
        let i = ref 0 in
        while !i < npts do
          let fl = u8 d !p in
          incr p;
          flags.(!i) <- fl;
          incr i;
          if fl land 8 <> 0 then begin
            let r = u8 d !p in
            incr p;
            for _ = 1 to r do
              if !i < npts then (flags.(!i) <- fl; incr i)
            done
          end
        done;
        let coords short same =
          let v = ref 0 in
          Array.map
            (fun fl ->
              (if fl land short <> 0 then begin
                 let b = u8 d !p in
                 incr p;
                 v := !v + if fl land same <> 0 then b else -b
               end
               else if fl land same = 0 then begin
                 v := !v + s16 d !p;
                 p := !p + 2
               end);
              float !v)
            flags
        in
        let xs = coords 2 16 in
        let ys = coords 4 32 in
        Array.mapi
          (fun c e ->
            let s = if c = 0 then 0 else ends.(c - 1) + 1 in
            if e < s || e >= npts then fail "bad contour in glyph %d" g;
            contour (Array.init (e - s + 1) (fun k -> (xs.(s + k), ys.(s + k), flags.(s + k) land 1 <> 0))))
          ends
      end
      else begin
        (* a composite: transformed copies of other glyphs *)
        let parts = ref [] and p = ref (o + 10) and more = ref true in
        while !more do
          let fl = u16 d !p and gi = u16 d (!p + 2) in
          p := !p + 4;
          let words = fl land 1 <> 0 and xy = fl land 2 <> 0 in
          let a1, a2 =
            if words then (let a = s16 d !p and b = s16 d (!p + 2) in p := !p + 4; (a, b))
            else
              let sb x = if x > 127 then x - 256 else x in
              let a = sb (u8 d !p) and b = sb (u8 d (!p + 1)) in
              p := !p + 2;
              (a, b)
          in
          let f2 q = float (s16 d q) /. 16384. in
          let a, b, c, e =
            if fl land 8 <> 0 then (let s = f2 !p in p := !p + 2; (s, 0., 0., s))
            else if fl land 64 <> 0 then (let sx = f2 !p and sy = f2 (!p + 2) in p := !p + 4; (sx, 0., 0., sy))
            else if fl land 128 <> 0 then begin
              let a = f2 !p and b = f2 (!p + 2) and c = f2 (!p + 4) and e = f2 (!p + 6) in
              p := !p + 8;
              (a, b, c, e)
            end
            else (1., 0., 0., 1.)
          in
          (* point-matched placement is not read: the part stays unmoved *)
          let dx, dy = if xy then (float a1, float a2) else (0., 0.) in
          let part = glyph_at f gi (depth + 1) in
          parts := Array.map (Array.map (transform (a, b, c, e, dx, dy))) part.contours :: !parts;
          more := fl land 32 <> 0
        done;
        Array.concat (List.rev !parts)
      end
    in
    { contours = Array.of_list (List.filter (fun c -> Array.length c > 0) (Array.to_list contours)); xmin; ymin; xmax; ymax }
  end

let glyph f g = glyph_at f g 0
