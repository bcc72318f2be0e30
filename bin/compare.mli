(** [camlray compare]: render scenes with POV-Ray and with camlray at the
    same size and anti-aliasing settings, and write a report (PSNR, SSIM,
    largest channel difference, both render times) with side-by-side and
    difference images. *)

val povray_available : unit -> bool

val run :
  inputs:string list -> width:int -> height:int -> aa:float option -> aa_depth:int ->
  out_dir:string -> include_dirs:string list -> limit:float option -> int
(** [limit]: the seconds each renderer may take a scene (POV-Ray is
    killed, camlray's render cancelled, past it; the scene is reported as
    having run past the limit). Exit code: 0 when every scene was rendered by both (or when POV-Ray is
    not installed: a message says nothing was compared), 1 otherwise.
    Writes [out_dir/report.md] and [out_dir/report.tsv] (scene, psnr,
    ssim, max_diff, povray_s, camlray_s). *)

val cmd :
  aa_args:(float option * int) Cmdliner.Term.t -> include_path:string list Cmdliner.Term.t ->
  int Cmdliner.Cmd.t
