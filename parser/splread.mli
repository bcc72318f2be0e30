(** Splines in the scene text: [spline { [S] [kind] t, v [,] ... }] and
    calls [S(t)] / [S(t, kind)]. Values may follow each other without a
    comma, as POV-Ray allows; the value's end is found on the raw tokens
    and the parser handed a ';' there ({!Cursor.t.stop_at}). *)

val read : Cursor.t -> Loc.t -> Spline.t
(** After the word [spline]. *)

val call : Cursor.t -> Spline.t -> Loc.t -> float array
(** After a spline's name: the value at the parameter. *)
