(** Random scene inputs for robustness testing: token soups built from
    the scene language's vocabulary, and mutations of real scenes. *)

val corpus : unit -> (string * string) list
(** [(name, text)]: scenes/ and test/golden/ files of this repository
    (found from the current folder upward) and a few POV-Ray example
    scenes when installed. *)

val token_soup : Random.State.t -> string
(** A random sequence of keywords, punctuation, numbers, identifiers,
    strings and directives. *)

val mutate : Random.State.t -> string -> string
(** One to four random edits of a text: delete, duplicate or move a
    span, insert a token, flip a character, truncate. *)

val input : Random.State.t -> (string * string) list -> string
(** A token soup or a mutated corpus file, half each. *)

type outcome = Accepted | Rejected | Crashed of string | Hung
(** [Hung]: still parsing after [timeout] seconds *)

val check : ?timeout:int -> string -> outcome
(** Parse and compile a text with small limits; [Crashed] when an OCaml
    exception escapes or the parser reports an "internal error" (an
    exception it caught as a last resort): neither must ever happen. Output of [#debug] and
    warnings goes to stderr. *)

val with_stderr_silenced : (unit -> 'a) -> 'a
