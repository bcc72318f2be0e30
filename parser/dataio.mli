(** POV-Ray's data files: [#fopen ID "file" read|write|append],
    [#write (ID, items...)] (strings as they are, floats as [%g], vectors
    as [<a,b,c> ]), [#read (ID, vars...)] (comma-separated numbers,
    vectors, strings; the end of the data closes the file and undefines
    ID) and [#fclose ID]. *)

val fopen : Cursor.t -> Loc.t -> unit
val write : Cursor.t -> Loc.t -> unit
val read : Cursor.t -> Loc.t -> unit
val fclose : Cursor.t -> unit

val close_files : Cursor.t -> unit
(** Close every file still open (end of a parse). *)
