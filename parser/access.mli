(** What a scene may read. A scene file is a program, often someone
    else's: [#include], [image_map] and every other read are confined to
    the folders of the include search order (the current folder, the
    scene's folder, [--include-path] folders, POV-Ray's include folder) and
    to folders granted with [--allow-read]; so are the files [#fopen]
    writes. Paths are compared after
    resolving symbolic links and [..], so neither an absolute path nor
    [../] escapes. *)

type t

val create : string list -> t
(** The allowed folders (they need not exist). *)

val unrestricted : t
(** Allows everything (for tests and embedded use). *)

val check : t -> string -> (unit, string) result
(** [check t path] is [Ok ()] when [path] lies inside an allowed folder,
    or [Error msg] naming the path and the folders that are allowed. *)

val folders : t -> string list
