(** Questions the scene language asks of a declared object while the
    scene is read: POV-Ray's [trace], [inside], [min_extent] and
    [max_extent]. The object is compiled once per parse (see {!reset}). *)

val extent : Loc.t -> Sdl.obj -> max:bool -> Camlray.Vec3.t
(** The corner of the object's world bounding box ([max]: the upper one);
    unbounded directions give POV-Ray's +-1e10. *)

val trace : Loc.t -> Sdl.obj -> Camlray.Vec3.t -> Camlray.Vec3.t -> Camlray.Vec3.t * Camlray.Vec3.t
(** [trace loc o start dir]: the first point where the ray from [start]
    along [dir] meets the object's surface, and the surface's outward unit
    normal there; [<0,0,0>] for both when it misses (POV-Ray's answer). *)

val inside : Loc.t -> Sdl.obj -> Camlray.Vec3.t -> bool
(** POV-Ray's inside test of the object at a point. *)

val object_pattern : Sdl.obj -> Camlray.Pattern.kind
(** POV-Ray's [object] pattern of the object (compiled on its own, lights
    dropped): 1 inside, 0 outside; an object that compiles to nothing is
    inside nowhere. *)

val reset : unit -> unit
(** Forget the compiled objects (a new parse starts). *)
