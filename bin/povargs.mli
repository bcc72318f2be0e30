(** POV-Ray's habits on camlray's command line: [+W800 +H600 +A0.3
    +Oout.png] switches and INI files are rewritten into camlray's own
    options before cmdliner sees the arguments (cmdliner would read [-A]
    as an unknown option). *)

type error = Misuse of string  (** exit 2 *) | Bad_file of string  (** exit 1 *)

val rewrite : warn:(string -> unit) -> string list -> (string list, error) result
(** [rewrite ~warn args] maps POV-Ray switches to camlray options and
    expands [.ini] arguments into the options their keys stand for.
    Arguments that are neither pass through unchanged. Switches that have
    no effect in camlray (display, pause, verbosity, file type PNG) are
    dropped with a warning; unknown switches and unknown INI keys are
    warned about by name. *)

val switches : (string * string) list
(** The POV-Ray switches camlray knows, with what they do (for the man
    page). *)
