(** [camlray obj2pov model.obj > model.inc]: convert a Wavefront OBJ file
    into POV-Ray [mesh2] declarations that camlray and POV-Ray both read.

    One [#declare OBJ_<group> = mesh2 { ... }] per group or object ([g] /
    [o]; faces before any of them go to [OBJ_<file>_default]), each with its
    own vertex list; polygons are triangulated as fans; normals are kept
    when every corner of a face has one ([vn]); faces without them get
    their flat normal so that [normal_indices] covers every face. Then
    [#declare OBJ_<file> = union { object { OBJ_<group> } ... }] (or an
    [object] for a single group). Coordinates are copied unchanged (OBJ is
    right-handed: mirror with [scale <1,1,-1>] if needed). Texture
    coordinates, materials and smoothing groups are ignored. *)

val convert : string -> (string, string) result
(** [convert path]: the include text, or an error ["file:line: message"]. *)

val run : string -> int
(** Print the conversion of the file on stdout; on error print it on
    stderr. The exit code: 0, or 1 on error. *)
