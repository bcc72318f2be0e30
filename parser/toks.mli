(** The tokens of a frame (a file, an include, a macro body), read by
    index. A file's tokens are lexed as the parser reaches them and can be
    released once it is past them, so that a scene of a million objects
    never holds all its tokens at once. *)

type t

type memo = ..
(** What a reader of the tokens keeps about them, by position (the
    arithmetic runs {!Fold} has read in a loop or a macro body, to read
    them again without their tokens). *)

type memo += Nothing

val memo : t -> memo
val set_memo : t -> memo -> unit

val of_array : Lexer.token array -> t
(** A fixed sequence (a macro body); its last token is [Eof]. *)

val of_text : file:string -> string -> t
(** The tokens of a file's text, lexed on demand. A lexical error is
    raised ({!Diag.Error}) when the parser reaches it. *)

val get : t -> int -> Lexer.token
(** Token [i]; past the end, the final [Eof]. Raises [Invalid_argument]
    for a released token (a bug: see {!release}). *)

val lexed : t -> int -> bool
(** Whether token [i] has been lexed and not released: {!get} reads it
    without lexing. *)

val mem : t -> int -> bool
(** Whether there is a token [i] (the final [Eof] included). *)

val sub : t -> int -> int -> Lexer.token array
(** [sub t pos len]: tokens [pos .. pos + len - 1]. *)

val release : t -> int -> unit
(** [release t i]: the tokens before [i] will not be read again. The
    [margin] tokens before [i] are kept; earlier ones may be freed. *)

val margin : int
