(* Helpers shared by the semantic actions of the grammar files. *)
open Camlray

let loc (s, e) = Loc.make s e
let v3 l v = Value.to_vec3 (loc l) v
let fl l v = Value.to_float (loc l) v
(* a pigment, normal or finish written on an object changes its texture's
   top layer; POV-Ray refuses one after a patterned texture *)
let with_texture l f (o : Sdl.obj) =
  let layers = match o.texture with Some t -> t | None -> [ Defaults.texture () ] in
  if Texture.is_patterned layers then Diag.error (loc l) "cannot layer over a patterned texture";
  match layers with
  | top :: rest -> { o with texture = Some (f top :: rest) }
  | [] -> o
(* a light's radius, falloff, tightness or point_at: POV-Ray refuses them
   on a point light (point_at is allowed on a parallel one) *)
let light_param (p1, p2) what ?(parallel = false) f (o : Sdl.obj) =
  match o.shape with
  | Sdl.Light l ->
      if l.kind = Sdl.Point_light && not (parallel && l.parallel) then
        Diag.error (loc (p1, p2))
          "%s needs a spotlight or a cylinder light%s: write spotlight or cylinder before it%s" what
          (if parallel then " (or parallel)" else "")
          (if l.shadowless then " (shadowless, written before, made this a point light)" else "");
      { o with shape = Sdl.Light (f l) }
  | _ -> o

(* projected_through { OBJECT }, once per light; the object is kept in the
   light's frame as it stands now, so that only the transformations
   written after it move it (as in POV-Ray) *)
let projected_through (p1, p2) (p : Sdl.obj) (o : Sdl.obj) =
  match o.shape with
  | Sdl.Light l ->
      if Option.is_some l.projected_through then
        Diag.error (loc (p1, p2)) "only one projected_through is allowed per light_source";
      let p = if Transform.is_identity o.xform then p else Sdl.transform_obj (Transform.inverse o.xform) p in
      { o with shape = Sdl.Light { l with projected_through = Some p } }
  | _ -> o
let light_field f (o : Sdl.obj) = match o.shape with
  | Sdl.Light l -> { o with shape = Sdl.Light (f l) } | _ -> o
let nonzero_scale l (v : Vec3.t) =
  let fix c = if c = 0. then (Diag.warning (loc l) "zero scale component replaced by 1"; 1.) else c in
  Vec3.make (fix v.x) (fix v.y) (fix v.z)

let area_field f (o : Sdl.obj) = match o.shape with
  | Sdl.Light ({ area = Some a; _ } as l) -> { o with shape = Sdl.Light { l with area = Some (f a) } }
  | _ -> o
(* [above] on top of [below], where POV-Ray allows it *)
let layered loc ~above ~below =
  match Texture.layering ~above ~below with
  | Some m -> Diag.error loc "%s" m
  | None -> above @ below

let top_layer f (t : Texture.t) = match t with top :: rest -> f top :: rest | [] -> []
let old_entry l1 v1 l2 v2 (c1, c2) = [ (fl l1 v1, c1); (fl l2 v2, c2) ]
let tmap_pattern (m : Texdesc.modifier) (l : Texture.layer) =
  match l.tmap with
  | None -> l
  | Some t -> (
      (* the layer's transformations so far: a warp is written after them *)
      match (m { (Texdesc.of_pattern Pattern.Bozo) with pattern = Some t.pattern; xform = t.xform }).pattern with
      | Some pattern -> { l with tmap = Some { t with pattern } }
      | None -> l)

(* a declared or current normal with more modifiers *)
let moved ms (n : Normal.t option) =
  Option.map
    (fun (n : Normal.t) ->
      Texdesc.normal (Texdesc.apply ms (Texdesc.of_normal n)))
    n

(* a normal_map entry written without a pattern: flat *)
let flat (n : Normal.t option) =
  match n with Some n -> n | None -> Texdesc.normal (Texdesc.of_pigment Pigment.black)

let slope vloc v range alt =
  let unit what l v =
    let d = v3 l v in
    let len = Vec3.length d in
    if len = 0. then Diag.error (loc l) "the %s direction of a slope pattern cannot be <0,0,0>" what;
    (Vec3.scale (1. /. len) d, len)
  in
  let span (lo, hi) = if lo = hi then Diag.error (loc vloc) "a slope range needs two different ends, found %g twice" lo in
  let dir, wdir = unit "slope" vloc v in
  let lo, hi = Option.value range ~default:(0., 1.) in
  span (lo, hi);
  let alt, walt, alo, ahi =
    match alt with
    | None -> (Vec3.unit_y, 0., 0., 1.)
    | Some (aloc, a, r) ->
        let d, w = unit "altitude" aloc a in
        let alo, ahi = Option.value r ~default:(0., 1.) in
        span (alo, ahi);
        (d, w, alo, ahi)
  in
  Pattern.Slope { dir; lo; hi; wdir; alt; alo; ahi; walt }

(* a mapping warp's orientation: normalised, as POV-Ray does *)
let orientation l v =
  let d = v3 l v in
  let len = Vec3.length d in
  if len = 0. then Diag.error (loc l) "a mapping warp's orientation cannot be <0,0,0>";
  Vec3.scale (1. /. len) d

(* the orientation and dist_exp a mapping warp's options leave (the last
   of each; z and 0 by default) *)
let mapping ms =
  List.fold_left
    (fun (o, e) m -> match m with `Orient v -> (v, e) | `Dist_exp x -> (o, x) | _ -> (o, e))
    (Vec3.unit_z, 0.) ms

(* an average texture: its weights over their sum, as POV-Ray divides *)
let average_texture l (layer : Texture.layer) =
  match layer.tmap with
  | Some m ->
      if Array.length m.entries = 0 then Diag.error l "an average texture needs a texture_map";
      let total = Array.fold_left (fun s (w, _) -> s +. w) 0. m.entries in
      if total = 0. then Diag.error l "the weights of an average's texture_map must not sum to 0";
      { layer with tmap = Some { m with entries = Array.map (fun (w, t) -> (w /. total, t)) m.entries } }
  | None -> layer

(* facets in a pigment or a texture: POV-Ray's error (it has no value) *)
let facets_elsewhere l =
  Diag.error (loc l) "facets can only be used in a normal (it tilts normals and has no value as a pigment pattern)"

(* POV-Ray 3.7's rainbow defaults: distance 1e7 (its largest distance),
   no jitter, angle and width 0 (nothing drawn until given), direction 0
   (an error: POV-Ray's), up y; arc_angle and falloff_angle checked and
   kept as POV-Ray keeps them (see Rainbow.make) *)
let rainbow loc items =
  let angle = ref 0. and width = ref 0. and distance = ref 1e7 and jitter = ref 0. in
  let dir = ref (loc, Vec3.zero) and up = ref (loc, Vec3.unit_y) in
  let arc = ref None and falloff = ref None and map = ref None in
  let degrees what (l, a) =
    if a < 0. || a > 360. then Diag.error l "a rainbow's %s must be from 0 to 360 degrees, found %g" what a;
    a *. Float.pi /. 360.
  in
  List.iter
    (function
      | `Angle a -> angle := a
      | `Width w -> width := w
      | `Distance d -> distance := d
      | `Jitter j -> jitter := j
      | `Direction d -> dir := d
      | `Up u -> up := u
      | `Arc a -> arc := Some (degrees "arc_angle" a)
      | `Falloff f -> falloff := Some (degrees "falloff_angle" f)
      | `Map m -> map := Some m)
    items;
  let arc = Option.value !arc ~default:180. in
  let falloff = Option.value !falloff ~default:arc in
  if arc < falloff then Diag.error loc "a rainbow's arc_angle is smaller than its falloff_angle";
  let (dl, d), (ul, u) = (!dir, !up) in
  if Vec3.length d < 1e-10 then Diag.error dl "a rainbow's direction must not be zero";
  if Vec3.length u < 1e-10 then Diag.error ul "a rainbow's up vector must not be zero";
  if Float.abs (1. -. Float.abs (Vec3.dot (Vec3.normalize u) (Vec3.normalize d))) < 1e-10 then
    Diag.error ul "a rainbow's up vector and direction must not be parallel";
  let pigment =
    match !map with
    | Some m -> Pigment.Map { pattern = Pattern.make (Pattern.Gradient Vec3.unit_x); entries = m; xform = Transform.identity }
    | None -> Diag.error loc "a rainbow needs a colour_map"
  in
  Rainbow.make ~angle:!angle ~width:!width ~distance:!distance ~jitter:!jitter ~direction:d ~up:u ~arc ~falloff pigment

(* an image_map's [filter ...] or [transmit ...] (POV-Ray takes no other
   channel there) *)
let image_channel l c =
  match c with
  | "filter" -> `Filter
  | "transmit" -> `Transmit
  | c -> Diag.error (loc l) "an image_map takes filter or transmit here, not %s" c

(* an image file type camlray reads where POV-Ray takes any *)
let readable_kind l k =
  match k with
  | "jpeg" | "ppm" | "gif" -> ()
  | k -> Diag.error (loc l) "%s images are not read by camlray here: png, jpeg, gif and ppm are" k

let vector_literal l cs =
  let n = List.length cs in
  (* 12 numbers are a matrix's argument (tested by the MATRIX rule) *)
  (* and the coefficients of a poly, cubic or quartic: 10, 20, 35 ... *)
  if (n < 2 || n > 5) && n <> 12
     && not (List.exists (fun k -> Algebraic.terms k = n) (List.init (Algebraic.max_order - 1) (fun k -> k + 2)))
  then
    Diag.error l "a vector has 2 to 5 components, this one has %d" n;
  Value.Vector (Array.of_list (List.map (fun c -> match c with
    | Value.Float f -> f
    | v -> Diag.error l "vector components must be floats, found %s" (Value.type_name v)) cs))

let call_function l f args =
  let args = List.map (Value.to_float l) args in
  if Fn.is_vector f then Value.Vector (Fn.call_vector l f args)
  else Value.Float (Fn.call l f args)

(* global_settings' radiosity { ... }: POV-Ray 3.7's words, each with
   its value (on/off words alone mean on); save_file and load_file are
   read and ignored (camlray keeps no radiosity data between renders) *)
type rad_item = Loc.t * string * (Loc.t * Value.t) option * (Loc.t * Value.t) option

let radiosity (items : rad_item list) =
  let value l w = function
    | Some (vl, v) -> (vl, Value.to_float vl v)
    | None -> Diag.error l "%s needs a value" w
  in
  let switch = function Some (vl, v) -> Value.to_float vl v <> 0. | None -> true in
  let int_in l w lo hi v =
    let n = int_of_float (Float.floor (v +. 0.5)) in
    if n < lo || n > hi then Diag.error l "radiosity %s %d: it takes %d to %d" w n lo hi;
    n
  in
  List.fold_left
    (fun (r : Radiosity.t) (l, w, v, more) ->
      (match (more, w) with
      | Some (ml, _), ("count" | "nearest_count") -> ignore ml
      | Some (ml, _), _ -> Diag.error ml "radiosity %s takes one value" w
      | None, _ -> ());
      match w with
      | "count" ->
          let vl, x = value l w v in
          { r with count = int_in vl w 1 1600 x }
      | "nearest_count" ->
          let vl, x = value l w v in
          { r with nearest_count = int_in vl w 1 20 x }
      | "recursion_limit" ->
          let vl, x = value l w v in
          { r with recursion_limit = int_in vl w 1 20 x }
      | "brightness" -> { r with brightness = snd (value l w v) }
      | "error_bound" ->
          let vl, x = value l w v in
          if not (x > 0.) then Diag.error vl "radiosity error_bound %g: it must be positive" x;
          { r with error_bound = x }
      | "gray_threshold" -> { r with gray_threshold = Float.min 1. (Float.max 0. (snd (value l w v))) }
      | "pretrace_start" -> { r with pretrace_start = snd (value l w v) }
      | "pretrace_end" -> { r with pretrace_end = snd (value l w v) }
      | "low_error_factor" -> { r with low_error_factor = snd (value l w v) }
      | "minimum_reuse" -> { r with minimum_reuse = snd (value l w v) }
      | "maximum_reuse" -> { r with maximum_reuse = snd (value l w v) }
      | "adc_bailout" -> { r with adc_bailout = snd (value l w v) }
      | "max_sample" -> { r with max_sample = snd (value l w v) }
      | "always_sample" -> { r with always_sample = switch v }
      | "normal" -> { r with normal = switch v }
      | "media" -> { r with media = switch v }
      | "subsurface" | "brilliance" ->
          if switch v then Defaults.warn_once ("radiosity " ^ w) l (Printf.sprintf "radiosity %s is read and ignored" w);
          r
      | "save_file" | "load_file" ->
          Defaults.warn_once "radiosity file" l
            "radiosity save_file and load_file are read and ignored: camlray gathers its radiosity anew at every render";
          r
      | _ -> Diag.error l "%s belongs in an object's radiosity block, not in global_settings" w)
    Radiosity.default items

(* an object's radiosity { importance ... }: read and ignored (camlray's
   gathers shoot every ray) *)
let object_radiosity l items =
  List.iter
    (fun (wl, w, v, _) ->
      match (w, v) with
      | "importance", Some (vl, v) -> ignore (Value.to_float vl v)
      | "importance", None -> Diag.error wl "importance needs a value"
      | _ -> Diag.error wl "radiosity %s is a global_settings word: an object's radiosity block takes importance" w)
    items;
  Defaults.warn_once "object radiosity" l
    "an object's radiosity { importance } is read and ignored: camlray's gathers shoot all their rays"

(* photons { ... }: a word and its values *)
type photon_item = Loc.t * string * (Loc.t * Value.t) list

let photon_values w n vs =
  if List.length vs > n then Diag.error (fst (List.nth vs n)) "photons %s takes at most %d value%s" w n (if n = 1 then "" else "s");
  List.map (fun (vl, v) -> (vl, Value.to_float vl v)) vs

let photon_one l w vs =
  match photon_values w 1 vs with [ (vl, x) ] -> (vl, x) | _ -> Diag.error l "photons %s needs a value" w

(* on/off words: alone they mean on; [refraction] and [reflection] need
   their value, as in POV-Ray *)
let photon_switch l w ~needs vs =
  match photon_values w 1 vs with
  | [ (_, x) ] -> x <> 0.
  | _ -> if needs then Diag.error l "photons %s needs on or off" w else true

let photons (items : photon_item list) =
  let int_at_least vl w lo x =
    let n = int_of_float (Float.floor (x +. 0.5)) in
    if n < lo then Diag.error vl "photons %s %d: it takes %d or more" w n lo;
    n
  in
  let s =
    List.fold_left
      (fun (s : Photon.settings) (l, w, vs) ->
        match w with
        | "spacing" ->
            let vl, x = photon_one l w vs in
            if not (x > 0.) then Diag.error vl "photons spacing %g: it must be positive" x;
            { s with spacing = x }
        | "count" ->
            let vl, x = photon_one l w vs in
            { s with count = int_at_least vl w 1 x }
        | "gather" -> (
            match photon_values w 2 vs with
            | [ (l1, a); (l2, b) ] ->
                let a = int_at_least l1 w 0 a and b = int_at_least l2 w 0 b in
                if a > b then Diag.error l "photons gather %d, %d: the minimum is above the maximum" a b;
                if b = 0 then Diag.error l2 "photons gather's maximum must be positive";
                { s with gather_min = a; gather_max = b }
            | _ -> Diag.error l "photons gather takes two values: the least and the most photons gathered")
        | "media" -> (
            match photon_values w 2 vs with
            | (l1, n) :: rest ->
                let n = int_at_least l1 w 0 n in
                let f =
                  match rest with
                  | (vl, f) :: _ ->
                      if not (f > 0.) then Diag.error vl "photons media's spacing factor %g: it must be positive" f;
                      f
                  | [] -> 1.
                in
                { s with media_steps = n; media_factor = f }
            | [] -> Diag.error l "photons media needs the most steps")
        | "jitter" -> { s with jitter = snd (photon_one l w vs) }
        | "max_trace_level" ->
            let vl, x = photon_one l w vs in
            { s with max_trace_level = int_at_least vl w 1 x }
        | "adc_bailout" -> { s with adc_bailout = snd (photon_one l w vs) }
        | "autostop" -> { s with autostop = snd (photon_one l w vs) }
        | "expand_thresholds" -> (
            match photon_values w 2 vs with
            | [ (_, a); (l2, b) ] -> { s with expand_tolerance = Float.max 0. a; expand_min = int_at_least l2 w 0 b }
            | _ -> Diag.error l "photons expand_thresholds takes two values: the tolerance and the least count")
        | "radius" -> (
            match photon_values w 4 vs with
            | [] -> s
            | (_, r) :: rest ->
                let nth k d = match List.nth_opt rest k with Some (_, v) -> v | None -> d in
                { s with radius = r; radius_mult = nth 0 1.; media_radius = nth 1 0.; media_mult = nth 2 1. })
        | "save_file" | "load_file" ->
            Defaults.warn_once "photon files" l (Printf.sprintf "photons %s is read and ignored: the photons are shot anew" w);
            s
        | _ -> Diag.error l "photons %s is not a global_settings word (an object's or a light's)" w)
      (Photon.default_settings ()) items
  in
  s

(* an object's or a light's photons { }, applied to what it modifies *)
let object_photons (items : photon_item list) (o : Sdl.obj) =
  let light = match o.shape with Sdl.Light _ -> true | _ -> false in
  let onoff b = if b then 1 else -1 in
  let p =
    List.fold_left
      (fun (p : Photon.flags) (l, w, vs) ->
        match (w, light) with
        | "refraction", _ -> { p with refraction = onoff (photon_switch l w ~needs:true vs) }
        | "reflection", _ -> { p with reflection = onoff (photon_switch l w ~needs:true vs) }
        | "area_light", true ->
            if vs <> [] then Diag.error l "photons area_light takes no value";
            { p with area_light = true }
        | "target", false -> (
            match photon_values w 1 vs with
            | [ (_, x) ] -> { p with target = Float.max 0. x }
            | _ -> { p with target = 1. })
        | "collect", false -> { p with collect = photon_switch l w ~needs:false vs }
        | "pass_through", false -> { p with pass_through = photon_switch l w ~needs:false vs }
        | "split_union", false -> { p with split_union = photon_switch l w ~needs:true vs }
        | _, true -> Diag.error l "a light's photons block takes refraction, reflection and area_light, not %s" w
        | _, false ->
            Diag.error l "an object's photons block takes target, refraction, reflection, collect, pass_through and split_union, not %s" w)
      o.photon items
  in
  (* POV-Ray: pass_through on a target that refracts is refused *)
  let p = if p.pass_through && p.target > 0. && p.refraction >= 0 then { p with pass_through = false } else p in
  { o with photon = p }
