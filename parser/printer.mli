(** Scene text from an evaluated scene description: the inverse of
    parsing for what {!Sdl} holds (objects with their shapes, transforms,
    textures and interiors; lights; background). Numbers are written with
    17 significant digits, so parsing the text gives the same numbers back;
    a transform is written as one [matrix]. Used by the round-trip tests
    and for debugging ([parse (print s)] = [s]). *)

val float : float -> string
val obj : Sdl.obj -> string
val item : Sdl.item -> string
val scene : Sdl.scene -> string
