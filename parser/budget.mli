(** The object budget of one parse (POV-Ray has none; camlray caps what an
    untrusted scene may make, [--max-objects]). Two counts share the
    limit: objects parsed (every shape and CSG read, placed or only
    declared, so a loop building one huge union stops early) and objects
    placed in the scene (every node of each top-level object, declared
    objects counted each time they are used). One parse runs at a time,
    like {!Defaults}. *)

val reset : int -> unit
(** Start a parse with this limit. *)

val parsed : Loc.t -> unit
(** One more object read at [loc]; a located error past the limit. *)

val place : Sdl.obj -> unit
(** A top-level object enters the scene; a located error when the scene's
    objects then exceed the limit. *)
