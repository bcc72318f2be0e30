open Camlray

type pat = {
  pattern : Pattern.t option;
  base : Pigment.t;
  entries : (float * Pigment.t) array option;
  cells : Pigment.t list;
  xform : Transform.t;
  amount : float;
  average : bool;  (** [average]: [entries] are weights, not values *)
  slope : Float.Array.t;
  accuracy : float;
  nmap : (float * Normal.t) array option;  (** normals: [normal_map] *)
  ncells : Normal.t list;  (** normals: block pattern normals, in written order *)
  bump : Bump_map.t option;
  facets : Facets.t option;  (** normals: [facets] *)
  uv : Normal.t option;
  carrier : Pattern.t option;
      (** the warps and turbulence written on what has no pattern of its
          own (image_map, average, bump_map), in a pattern whose kind is
          unused *)
}

type modifier = pat -> pat

let empty =
  { pattern = None; base = Pigment.black; entries = None; cells = []; xform = Transform.identity;
    amount = 0.5; average = false; slope = Float.Array.create 0;
    accuracy = Normal.default_accuracy; nmap = None; ncells = []; bump = None; facets = None; uv = None;
    carrier = None }

let of_pigment (p : Pigment.t) =
  match p with
  | Pigment.Map { pattern; entries; xform } ->
      { empty with pattern = Some pattern; entries = Some entries; xform; base = p }
  | Pigment.Blocks { pattern; cells; xform } ->
      { empty with pattern = Some pattern; cells = Array.to_list cells; xform; base = p }
  | Pigment.Image_map { warp; _ } | Pigment.Average { warp; _ } -> { empty with base = p; carrier = warp }
  | _ -> { empty with base = p }

let of_pattern k = { empty with pattern = Some (Pattern.make k) }

(* A normal's pattern starts as a copy of the #default normal, as
   POV-Ray's parser makes it (Parse_Tnormal copies the default): its
   amount, transformations, turbulence and warps, the pattern replaced
   (measured: under #default { normal { bump_size 1.5 scale 3 } },
   normal { marble } renders as marble 1.5 scale 3; a turbulence is
   kept the same way) *)
let of_normal_pattern k =
  let p = of_pattern k in
  match Defaults.normal_template () with
  | None -> p
  | Some (d : Normal.t) ->
      let t = Pattern.make k in
      { p with
        amount = d.amount;
        xform = d.xform;
        pattern = Some { t with turbulence = d.pattern.turbulence; warps = d.pattern.warps } }
let average () = { empty with average = true }

(* the pattern carries the warps and turbulence written; its kind is
   unused *)
let facets () = { empty with pattern = Some (Pattern.make Pattern.Bozo); facets = Some Facets.default }

let facets_mod loc word f p =
  match p.facets with
  | Some x -> { p with facets = Some (f x) }
  | None -> Diag.error loc "%s can only be used with facets" word
let apply ms p = List.fold_left (fun p m -> m p) p ms

let transform t p =
  match p.pattern with
  | _ when p.uv <> None -> { p with uv = Option.map (Normal.transform t) p.uv }
  | None when p.bump <> None -> { p with xform = Transform.then_ p.xform t }
  (* POV-Ray 3.7 moves an average's or a pattern's own point only
     (Transform_Tpattern): the entries of its map, written before or after,
     are taken at that point and follow it; an average pigment's entries
     are given its transform when it is built *)
  | None when p.average -> { p with xform = Transform.then_ p.xform t }
  | None -> { p with base = Pigment.transform t p.base }
  | Some _ -> { p with xform = Transform.then_ p.xform t }

(* POV-Ray 3.7 warps the point of an image map, a bump map and an
   average (pigment or normal) as it warps a pattern's (checked against
   its renders: repeat and black_hole warps) *)
let carries p =
  p.average || p.bump <> None
  || match p.base with Pigment.Image_map _ | Pigment.Average _ -> true | _ -> false

(* the transformations a warp written now comes after: an image map's
   (and a built average's) are its own, the others' in [xform] *)
let carrier_xform p =
  match p.base with
  | Pigment.Image_map { xform; _ } | Pigment.Average { xform; _ } -> xform
  | _ -> p.xform

let carrier p = match p.carrier with Some c -> c | None -> Pattern.make Pattern.Bozo

let pattern_mod f p =
  match p.pattern with
  | Some pt -> { p with pattern = Some (f pt) }
  | None when carries p -> { p with carrier = Some (f (carrier p)) }
  | None -> p

let turbulence v =
  pattern_mod (fun pt ->
      let tb =
        match pt.turbulence with
        | Some tb -> { tb with amount = v }
        | None -> Pattern.default_turbulence v
      in
      { pt with turbulence = Some tb })

(* a change to the pattern's classic turbulence, made (of amount 0) if
   it has none *)
let turb_mod f =
  pattern_mod (fun pt ->
      let tb = match pt.turbulence with Some tb -> tb | None -> Pattern.default_turbulence Vec3.zero in
      { pt with turbulence = Some (f tb) })

(* POV-Ray's Check_BH_Parameters, run when a black hole's repeat or
   turbulence is read (once it repeats): on each repeated axis (its
   component positive) the centre at least the radius from the cell's
   corner, and the cell at least centre + radius + turbulence wide
   (widened with POV-Ray's warning) *)
let check_black_hole loc (k : Pattern.warp_kind) =
  match k with
  | Pattern.Black_hole ({ center = c; radius; repeat = r; jitter = u; _ } as h)
    when r.x > 0. || r.y > 0. || r.z > 0. ->
      let axis name c r u =
        if r > 0. then begin
          let c = if c < radius then radius else c in
          let need = c +. radius +. u in
          let r =
            if r < need then begin
              Diag.warning loc (Printf.sprintf "black hole repeat vector %s too small: increased to %g" name need);
              need
            end
            else r
          in
          (c, r)
        end
        else (c, r)
      in
      let cx, rx = axis "x" c.x r.x u.x and cy, ry = axis "y" c.y r.y u.y and cz, rz = axis "z" c.z r.z u.z in
      Pattern.Black_hole { h with center = Vec3.make cx cy cz; repeat = Vec3.make rx ry rz }
  | k -> k

let map es p = { p with entries = Some (Array.of_list es) }
let kind_mod f = pattern_mod (fun pt -> { pt with kind = f pt.kind })

let metric x p =
  match p.facets with
  | Some f -> { p with facets = Some { f with metric = x } }
  | None -> kind_mod (function Pattern.Crackle c -> Pattern.Crackle { c with metric = x } | k -> k) p

(* density_file df3 "file": found beside the scene or on the include
   path, as POV-Ray looks for it *)
let density_file loc file =
  let path =
    match Defaults.find_file loc file with
    | Some p -> p
    | None -> Diag.error loc "cannot find density_file %s (looked in the scene's folder and the include path)" file
  in
  match Pattern.read_df3 path with
  | d -> Pattern.Density_file d
  | exception (Failure e | Sys_error e) -> Diag.error loc "cannot read density_file %s: %s" file e

let pigment p =
  match p.pattern with
  | None when p.average ->
      (* POV-Ray divides by the weights' sum *)
      let es = Option.value ~default:[||] p.entries in
      let total = Array.fold_left (fun s (w, _) -> s +. w) 0. es in
      if Array.length es = 0 || total = 0. then Pigment.black
      else Pigment.Average { entries = Array.map (fun (w, q) -> (w /. total, q)) es; xform = p.xform; warp = p.carrier }
  | None -> (
      match p.base with
      | Pigment.Image_map i -> Pigment.Image_map { i with warp = p.carrier }
      | Pigment.Average a -> Pigment.Average { a with warp = p.carrier }
      | b -> b)
  | Some pattern ->
      if Pattern.is_block pattern.kind then
        let defaults = Array.map snd (Pigment.default_entries pattern.kind) in
        let given = Array.of_list p.cells in
        let cells =
          Array.init (Pattern.block_count pattern.kind) (fun i ->
              if i < Array.length given then given.(i) else defaults.(i))
        in
        Pigment.Blocks { pattern; cells; xform = p.xform }
      else
        let entries =
          match p.entries with Some e -> e | None -> Pigment.default_entries pattern.kind
        in
        Pigment.Map { pattern; entries; xform = p.xform }

let built_normal p =
  let leaf pattern amount =
    { Normal.pattern; amount; xform = p.xform; slope = p.slope; accuracy = p.accuracy; map = Normal.Leaf }
  in
  match (p.pattern, p.facets) with
  | _, Some f ->
      let pattern = Option.value p.pattern ~default:(Pattern.make Pattern.Bozo) in
      { (leaf pattern p.amount) with map = Normal.Facets f }
  | pattern, None ->
  match pattern with
  | None when p.bump <> None -> { (leaf (carrier p) p.amount) with map = Normal.Image (Option.get p.bump) }
  | None when p.average ->
      (* POV-Ray divides by the weights' sum *)
      let es = Option.value ~default:[||] p.nmap in
      let total = Array.fold_left (fun s (w, _) -> s +. w) 0. es in
      let n = leaf (carrier p) 0. in
      if Array.length es = 0 || total = 0. then n
      else { n with map = Normal.Average (Array.map (fun (w, q) -> (w /. total, q)) es) }
  | None -> leaf (Pattern.make Pattern.Bozo) 0.
  | Some pattern when Pattern.is_block pattern.kind && p.ncells <> [] ->
      let given = Array.of_list p.ncells in
      (* cells left out are flat *)
      let flat = { (leaf (Pattern.make Pattern.Bozo) 0.) with xform = Transform.identity } in
      let cells =
        Array.init (Pattern.block_count pattern.kind) (fun i -> if i < Array.length given then given.(i) else flat)
      in
      { (leaf pattern p.amount) with map = Normal.Cells cells }
  | Some pattern -> (
      match p.nmap with
      | Some es when Array.length es > 0 -> { (leaf pattern p.amount) with map = Normal.Blend es }
      | _ -> leaf pattern p.amount)

let normal p = match p.uv with Some n -> n | None -> built_normal p

let of_normal (n : Normal.t) =
  let p = { empty with xform = n.xform; amount = n.amount; slope = n.slope; accuracy = n.accuracy } in
  match n.map with
  | Normal.Average es -> { p with average = true; nmap = Some es; carrier = Some n.pattern }
  | Normal.Leaf -> { p with pattern = Some n.pattern }
  | Normal.Blend es -> { p with pattern = Some n.pattern; nmap = Some es }
  | Normal.Cells cs -> { p with pattern = Some n.pattern; ncells = Array.to_list cs }
  | Normal.Image b -> { p with bump = Some b; carrier = Some n.pattern }
  | Normal.Facets f -> { p with pattern = Some n.pattern; facets = Some f }
  | Normal.Uv _ -> { p with uv = Some n }

let normal_map loc es p =
  if es = [] then Diag.error loc "a normal_map needs at least one entry";
  let rec sorted = function
    | (v0, _) :: ((v1, _) :: _ as rest) ->
        if v1 < v0 && not p.average then
          Diag.error loc "normal_map entries must come in order of value (%g after %g)" v1 v0;
        sorted rest
    | _ -> ()
  in
  sorted es;
  (* POV-Ray divides by the sum: 0 gives it no normal (black) *)
  if p.average && List.fold_left (fun s (w, _) -> s +. w) 0. es = 0. then
    Diag.error loc "the weights of an average's normal_map must not sum to 0";
  { p with nmap = Some (Array.of_list es) }

type image_mod =
  | Every of (Pigment.image -> Pigment.image)
  | Entry of { loc : Loc.t; channel : [ `Filter | `Transmit ]; entry : float; amount : float }

let image_map loc ?file_gamma ~gamma_decode file mods =
  (* beside the scene or on the include path, as POV-Ray looks *)
  let path =
    match Defaults.find_file loc file with
    | Some p -> p
    | None -> Diag.error loc "cannot find image_map %s (looked in the scene's folder and the include path)" file
  in
  let img =
    try Image.read path
    with Sys_error e | Failure e -> Diag.error loc "cannot read image_map %s: %s" file e
  in
  let dec x =
    let c = float_of_int x /. 255. in
    (* png "file" gamma G: the file's values are c^G; decoded colours
       are carried into the working gamma's space (measured: an image at
       ambient 1 shows the file's values under assumed_gamma 2.2) *)
    match file_gamma with
    | Some g -> Value.to_working (Float.pow c g)
    | None -> if gamma_decode then Value.srgb_decode c else c
  in
  (* an alpha channel (or a palette's tRNS) is the pixels' transmit,
     1 - alpha, as in POV-Ray *)
  let alphas =
    try Image.read_alpha path with Sys_error e | Failure e -> Diag.error loc "cannot read image_map %s: %s" file e
  in
  let px =
    Array.init (img.w * img.h) (fun i ->
        let b k = dec (Char.code (Bytes.get img.data ((3 * i) + k))) in
        let c = Color.opaque (Color.make (b 0) (b 1) (b 2)) in
        match alphas with
        | Some a -> { c with transmit = 1. -. (float_of_int (Char.code (Bytes.get a i)) /. 255.) }
        | None -> c)
  in
  let im = { Pigment.w = img.w; h = img.h; px; once = false; interpolate = 0; map_type = 0 } in
  (* the palette's entry of each pixel, read when a change names one *)
  let palette =
    lazy
      (try
         match Image.read_palette path with Some (_, _, idx, n) -> Some (idx, n) | None -> None
       with Sys_error e | Failure e -> Diag.error loc "cannot read image_map %s: %s" file e)
  in
  let apply (i : Pigment.image) = function
    | Every f -> f i
    | Entry { loc; channel; entry; amount } -> (
        let name = match channel with `Filter -> "filter" | `Transmit -> "transmit" in
        match Lazy.force palette with
        | None ->
            Diag.error loc
              "%s %g, %g sets a palette entry, and %s has no palette (%s all %g acts on every pixel of any image)"
              name entry amount file name amount
        | Some (idx, n) ->
            let k = int_of_float (entry +. 0.01) in
            if k < 0 || k >= n then
              Diag.error loc "palette entry %d is out of range: %s has %d (0 to %d)" k file n (n - 1);
            let set (p : Color.rgbft) =
              match channel with `Filter -> { p with filter = amount } | `Transmit -> { p with transmit = amount }
            in
            { i with px = Array.mapi (fun j p -> if Char.code (Bytes.get idx j) = k then set p else p) i.px })
  in
  Pigment.Image_map { image = List.fold_left apply im mods; xform = Transform.identity; warp = None }

(* a PNG's bit depth and colour type (IHDR's bytes 24 and 25; colour
   type 3 is a palette, 0 grey), [None] for other files *)
let png_kind file =
  match In_channel.with_open_bin file (fun ic -> really_input_string ic 26) with
  | s when String.sub s 0 8 = Png_codec.signature -> Some (Char.code s.[24], Char.code s.[25])
  | _ -> None
  | exception (Sys_error _ | End_of_file) -> None

(* a palette image: a palette PNG, or a GIF (always one) *)
let png_palette file =
  match png_kind file with
  | Some (_, 3) -> true
  | Some _ -> false
  | None -> (
      match In_channel.with_open_bin file (fun ic -> really_input_string ic 6) with
      | s -> Image.is_gif s
      | exception (Sys_error _ | End_of_file) -> false)

(* single precision, as POV-Ray's colours are *)
let single = Camlray.Floats.single

(* How POV-Ray 3.7 keeps a grey PNG of 8 bits or fewer (png.cpp: as a
   table of colours stored into a byte image): the colour [c], decoded,
   turned to grey in single precision (0.297 c + 0.589 c + 0.114 c,
   which falls below c for many c) and truncated to a byte. 84 of the
   256 levels of an 8-bit grey image read one level lower: 3 as 2/255,
   90 as 89/255 (measured on a 16 x 16 image of every level, through
   image_pattern and image_map alike; this rule gives exactly those 84) *)
let grey_byte c =
  let a = single 0.297 and b = single 0.589 and d = single 0.114 and c = single c in
  let g = single (single (single (c *. a) +. single (c *. b)) +. single (c *. d)) in
  Float.of_int (int_of_float (single (g *. 255.))) /. 255.

(* image_pattern { FILE ... }: the number of each pixel, as POV-Ray 3.7
   reads it (measured with pigment functions on 8 x 8 PNGs of every
   colour type, #version 3.7 and assumed_gamma 1): the grey 0.297 r +
   0.589 g + 0.114 b of the file's values as they are (not decoded from
   sRGB: image patterns are not gamma-corrected), of a palette's colours
   with or without use_index; with [gamma G] after the file the values
   decoded as c^G first. use_alpha: 1 - alpha where the image has an
   alpha channel or a palette (a palette without tRNS gives 0
   everywhere), the red channel where it has neither. *)
let image_pattern loc ?file_gamma ~alpha ~interpolate ~once ~map_type file =
  let path =
    match Defaults.find_file loc file with
    | Some p -> p
    | None -> Diag.error loc "cannot find image_pattern image %s (looked in the scene's folder and the include path)" file
  in
  let fail e = Diag.error loc "cannot read image_pattern %s: %s" file e in
  let img = try Image.read path with Sys_error e | Failure e -> fail e in
  let alphas = if alpha then try Image.read_alpha path with Sys_error e | Failure e -> fail e else None in
  let dec = match file_gamma with Some g -> fun c -> Float.pow c g | None -> Fun.id in
  let dec = match png_kind path with Some (d, 0) when d <= 8 -> fun c -> grey_byte (dec c) | _ -> dec in
  let c i k = dec (float_of_int (Char.code (Bytes.get img.data ((3 * i) + k))) /. 255.) in
  let value i =
    match alphas with
    | Some a -> 1. -. (float_of_int (Char.code (Bytes.get a i)) /. 255.)
    | None -> if alpha then c i 0 else Bump_map.grey (c i 0) (c i 1) (c i 2)
  in
  let values = Float.Array.init (img.w * img.h) value in
  Pattern.Image (Bump_map.make ~map_type ~w:img.w ~h:img.h ~once ~interpolate ~by_index:false values)


let bump_map loc file ~index ~interpolate ~once =
  let file =
    match Defaults.find_file loc file with
    | Some p -> p
    | None -> Diag.error loc "cannot find bump_map image %s (looked in the scene's folder and the include path)" file
  in
  let palette = png_palette file in
  let fail e = Diag.error loc "cannot read bump_map %s: %s" file e in
  (* POV-Ray 3.7 reads a bump map's colours unless use_index (measured on
     a palette PNG: no keyword and use_color alike, use_index apart); by
     index, the heights are the palette's indices as they are, 0 to 255
     (imageutil.cpp's bump_map: Amount * index), a relief far steeper
     than the colours' *)
  let by_palette = palette && index = Some true in
  if by_palette && interpolate <> 0 then
    Diag.error loc
      "an interpolated bump_map by palette index is not supported by camlray (%s): leave out interpolate, or add use_color"
      file;
  let img = try Image.read file with Sys_error e | Failure e -> fail e in
  let heights =
    if by_palette then
      match Image.read_indices file with
      | Some (_, _, idx) -> Float.Array.init (img.w * img.h) (fun i -> float_of_int (Char.code (Bytes.get idx i)))
      | None -> fail "no palette read"
      | exception (Sys_error e | Failure e) -> fail e
    else
      let c i k = float_of_int (Char.code (Bytes.get img.data ((3 * i) + k))) /. 255. in
      Float.Array.init (img.w * img.h) (fun i -> Bump_map.grey (c i 0) (c i 1) (c i 2))
  in
  let b = Bump_map.make ~w:img.w ~h:img.h ~once ~interpolate ~by_index:(index = Some true) heights in
  { empty with bump = Some b; amount = 0.5 }

let material_map loc file ~once ~count =
  if count = 0 then Diag.error loc "a material_map needs at least one texture";
  let file =
    match Defaults.find_file loc file with
    | Some p -> p
    | None -> Diag.error loc "cannot find material_map image %s (looked in the scene's folder and the include path)" file
  in
  let fail e = Diag.error loc "cannot read material_map %s: %s" file e in
  (* a palette image's indices, else the red bytes (not gamma-decoded: measured) *)
  let w, h, numbers =
    match Image.read_indices file with
    | Some (w, h, b) -> (w, h, b)
    | None ->
        let img = Image.read file in
        (img.w, img.h, Bytes.init (img.w * img.h) (fun i -> Bytes.get img.data (3 * i)))
    | exception (Sys_error e | Failure e) -> fail e
  in
  Pattern.Material { w; h; once; numbers; count }

let slope_map loc entries p =
  let rec sorted = function
    | (v0, _, _) :: ((v1, _, _) :: _ as rest) ->
        if v1 < v0 then Diag.error loc "slope_map entries must come in order of value (%g after %g)" v1 v0;
        sorted rest
    | _ -> ()
  in
  if entries = [] then Diag.error loc "a slope_map needs at least one entry";
  sorted entries;
  { p with slope = Float.Array.of_list (List.concat_map (fun (v, h, s) -> [ v; h; s ]) entries) }

let warp loc k p =
  let add (pt : Pattern.t) xform = { pt with warps = Array.append pt.warps [| Pattern.warp xform k |] } in
  match p.pattern with
  | Some pt -> { p with pattern = Some (add pt p.xform) }
  | None when carries p -> { p with carrier = Some (add (carrier p) (carrier_xform p)) }
  | None ->
      Diag.warning loc "a warp on a plain colour changes nothing";
      p

let accuracy loc a p =
  if not (a > 0.) then Diag.error loc "a normal's accuracy must be positive, found %g" a;
  { p with accuracy = a }
