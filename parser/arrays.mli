(** Arrays: [array[n][m] { ... }] declarations, indexing, copying, and
    the queries [defined()], [dimensions()], [dimension_size()]. *)

val query : Cursor.t -> string -> Loc.t -> float
(** [query t what loc] with [what] one of "defined", "dimensions",
    "dimension_size", after the keyword: reads the parenthesised
    argument and returns the answer. *)

val element : Cursor.t -> string -> Env.binding option array -> Loc.t -> Decl.t
(** After an array's name: read [[i]]... and return the element. *)

val copy : Env.binding option array -> Env.binding option array
(** A deep copy ([#declare B = A]). *)

val make : Cursor.t -> Loc.t -> Env.binding option array
(** After [array]: read the sizes and an optional initialiser list
    (trailing comma allowed). *)
