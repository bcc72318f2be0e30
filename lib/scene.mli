(** A compiled scene: what the renderers see. Built by the scene-language
    compiler; no syntax here. *)

type settings = {
  max_trace_level : int;  (** 1..256, default 5 *)
  adc_bailout : float;  (** default 1/255 *)
  ambient_light : Color.t;
  encoding : Image.encoding;  (** output transfer curve (POV-Ray's gamma rules) *)
  legacy_alpha : bool;
      (** pre-3.7 transparency rule: alpha = 1 - (f max(rgb) + t) *)
  irid_wavelength : Color.t;  (** [irid_wavelength], POV-Ray's <0.25, 0.18, 0.14> by default *)
  radiosity : Radiosity.t option;  (** global_settings' [radiosity], computed in whitted mode *)
  photons : Photon.settings option;  (** global_settings' [photons], shot in whitted mode *)
  object_media : bool;
      (** the media of objects are computed (true; false in the view of
          radiosity's gather rays unless its [media on], as POV-Ray) *)
}

type accel
(** The acceleration structure over [objects]: a BVH over the finite ones,
    the infinite ones (planes, inverted shapes, CSG without bounds) kept
    aside and tested on every ray. *)

type t = {
  objects : Object.t array;
  lights : Light.t array;  (** the global lights: those outside any [light_group] *)
  light_sets : Light.t array array;
      (** the lights of each surface, by its {!Object.t.lights}: [lights]
          first (physically the same array), then one set per light group
          placed (its own lights, after the global ones with
          [global_lights on]) *)
  camera : Camera.t;
  background : Color.t;
  sky : Sky.t;  (** sky_sphere; {!Sky.none} when absent *)
  fog : Fog.t list;  (** in source order; whitted mode draws them *)
  rainbows : Rainbow.t list;  (** in source order; whitted mode draws them *)
  atmosphere : Interior.t list;
      (** scene-level (atmospheric) media: [[]], or one hollow interior
          holding them in source order (see {!atmosphere}); whitted mode
          draws them where a ray is in the open *)
  settings : settings;
  accel : accel;
      (** built from [objects] by {!accelerate} (see {!with_objects}); for
          nearest hits. In a view ({!image}, {!reflected}) it lacks the
          objects hidden from that view. *)
  all : accel;  (** every object: for shadows and for what holds a point *)
  views : views;
}

and views = { mutable image : t option; mutable reflected : t option; mutable gather : t option }
(** [None]: the scene itself (nothing hidden from that view). *)

val with_objects : t -> Object.t array -> accel -> t
(** The scene with other objects and their tree; no hidden objects. *)

val hide : t -> int array -> t
(** [hide s flags]: POV-Ray's [no_image] (bit 1 of [flags.(i)]),
    [no_reflection] (bit 2) and [no_radiosity] (bit 16) for
    [s.objects.(i)]: the scene with views that leave those objects out
    (each view has its own tree), and its {!radiosity} view when it has
    radiosity. *)

val image : t -> t
(** What camera rays, and rays refracted from them, see: the scene
    without its [no_image] objects (shadows still see them). *)

val reflected : t -> t
(** What rays after a reflection see: without its [no_reflection] objects. *)

val radiosity : t -> t
(** What radiosity's gather rays see (set by {!hide} when the scene has
    radiosity): without its [no_radiosity] objects, area lights shading
    as the point at their centre, scene media only with the radiosity's
    [media on], and the radiosity's ADC bailout; its reflected view
    leaves out the [no_reflection] objects too. *)

val accelerate : ?par:(int -> (int -> unit) -> unit) -> Object.t array -> accel
(** Build the BVH (binned SAH) over the objects' world bounds; with [par],
    in parallel (see {!Bvh.build}; the same tree). *)

val atmosphere : Media.t list -> Interior.t list
(** The [atmosphere] field for scene-level media. *)

val make :
  ?sky:Sky.t -> ?fog:Fog.t list -> ?rainbows:Rainbow.t list -> ?media:Media.t list -> ?groups:Light.t array array -> objects:Object.t array ->
  lights:Light.t array -> camera:Camera.t ->
  background:Color.t -> settings:settings -> unit -> t
(** A scene with its acceleration structure built; [groups]: the light
    sets after the global one (by default none). *)

val all_lights : t -> Light.t array
(** Every light of every set, each once, the global ones first. *)

val bvh_nodes : t -> int
(** Number of BVH nodes over the finite objects (for reports). *)

val default_settings : settings

type hit = { t : float; obj : Object.t; point : Vec3.t; normal : Vec3.t }
(** [normal] is the object's outward unit normal (not yet flipped toward
    the ray). *)

val nearest : t -> Ray.scratch -> float -> Hit.t -> Object.found -> bool
(** [nearest s ray tmin h f]: the nearest hit in [(tmin, h.t)], into [h]
    and [f.leaf] ([h.id < 0] marks a sphere tested from the flat array:
    {!intersect} knows its normal). The allocation-free query that
    {!intersect} wraps (for kernels and benchmarks). *)

val intersect : t -> Ray.t -> float -> float -> hit option
(** Nearest hit in [(tmin, tmax)]. *)

val intersect_into : t -> Vec3.m -> Vec3.m -> float -> float -> Hit.t -> Object.found -> bool
(** [intersect_into s origin dir tmin tmax h f]: {!intersect} without
    allocating, the ray in vectors written in place: the distance and part
    into [h], the object into [f.leaf] (records the caller owns; read them
    before the next query). *)

type query
(** The records of a query of the scene (its ray, the traversal stack of
    the domain that made them): {!intersect_into} and {!occluders_s}
    look up the domain's own per query; a caller that queries often
    keeps one, used on its domain only and for one query at a time. *)

val query : unit -> query
(** New query records, for the calling domain. *)

val intersect_with : t -> query -> Vec3.m -> Vec3.m -> float -> float -> Hit.t -> Object.found -> bool
(** {!intersect_into} with the caller's query records. *)

val hit_records : unit -> Hit.t * Object.found
(** The calling domain's records for {!intersect_into} (which {!intersect}
    uses too): read them before the next query. *)

val new_records : unit -> Hit.t * Object.found
(** A new pair of records for {!intersect_into}, the caller's own. *)

val hit_normal : t -> Object.found -> Hit.t -> Vec3.t -> Vec3.t
(** The outward unit normal at the point of a hit found by
    {!intersect_into}. *)

val hit_normal_into : t -> Object.found -> Hit.t -> Vec3.m -> Vec3.m -> unit
(** [hit_normal_into s f h p n]: {!hit_normal} at [p], written into [n];
    allocates nothing for spheres of the flat array and untransformed
    planes, discs, boxes, triangles and meshes. *)

(** Objects in a growing array: the first [n] of [items]. *)
type objects = { mutable items : Object.t array; mutable n : int }

val objects : unit -> objects
val add_object : objects -> Object.t -> unit

val same_objects : objects -> objects -> bool
(** The same objects (physically), in the same order. *)

val containing_into : t -> Vec3.m -> objects -> unit
(** {!containing} of a point written in place, into [out] (allocating
    only to grow it). *)

val containing_m : t -> Vec3.m -> Object.t list
(** {!containing} of a point written in place. *)

val containing : t -> Vec3.t -> Object.t list
(** The objects whose inside (POV-Ray's test) holds the point, the last
    in [objects] first; objects whose box is away from the point are not
    tested. *)

val occluded : t -> Ray.t -> float -> float -> bool
(** Any-hit query: some shadow-casting surface in [(tmin, tmax)]. *)

val occluders :
  t -> Ray.t -> float -> float -> (Object.t -> bool) -> (Object.t -> float -> bool) -> bool
(** [occluders s ray tmin tmax opaque f] calls [f obj t] on every
    shadow-casting object hit in [(tmin, tmax)] (in no particular order)
    until [f] returns [false]; returns [false] if some call did. [f obj t]
    must be [false] at every crossing of an object for which [opaque obj]
    holds: such an object is not passed to [f] (the walk stops there) and
    may be asked for one crossing, not all (see {!Object.crossings_s});
    {!Object.never} when nothing is known. *)

val occluders_s :
  t -> Ray.scratch -> float -> (Object.t -> bool) -> (Object.t -> Hit.t -> bool) -> bool
(** [occluders_s s ray tmin opaque f]: [occluders] of a ray held in a
    scratch record, within [(tmin, ray.far)], [f obj h] reading the
    crossing's distance in [h.t] (a distance passed would be boxed). With
    [opaque] and [f] closed functions, a walk allocates nothing. *)

val occluders_with :
  t -> query -> Ray.scratch -> float -> (Object.t -> bool) -> (Object.t -> Hit.t -> bool) -> bool
(** {!occluders_s} with the caller's query records. *)
