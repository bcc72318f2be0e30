(** Conditionals, loops and [#switch]: entering and leaving the open
    structures of the current frame, and skipping untaken branches. *)

val enter_if : Cursor.t -> Loc.t -> bool -> unit
(** After [#if (c)] (or [#ifdef]): run the branch, or skip to the
    [#elseif]/[#else] that applies. *)

val skip_to_end : Cursor.t -> unit
val skip_condition : Cursor.t -> unit
(** Skip a parenthesised condition without evaluating it. *)

val end_block : Cursor.t -> Loc.t -> unit
(** [#end]: close an [#if]/[#switch], or loop back in [#while]/[#for]
    (with the iteration limit). *)

val for_loop : Cursor.t -> Loc.t -> unit
(** [#for (V, start, stop [, step])] *)

val switch : Cursor.t -> Loc.t -> unit
val break : Cursor.t -> Loc.t -> unit
