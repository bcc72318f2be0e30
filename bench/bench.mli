(** Scene size against trace time: spheres filling a cube (written in the
    scene language and parsed), spheres covering a sphere's surface and
    triangle meshes (a subdivided sphere, a heightfield terrain), these
    three generated in code, from 10 to 10^6 objects filling the same
    volume and the same part of the screen, at a fixed resolution. Parse,
    BVH build and trace times are reported separately. *)

type row = {
  kind : string;
  count : int;
  parse_s : float;  (** scene text to compiled scene, BVH excluded *)
  build_s : float;  (** BVH build (scene level, or mesh level) *)
  trace_s : float;  (** Whitted render of the image *)
  bytes_per_prim : float;  (** {!Camlray.Mesh.bytes} / triangles (meshes) *)
}

val run : ?sizes:int list -> ?width:int -> ?height:int -> ?domains:int -> unit -> row list
(** Run every workload at every size (default 10, 10^3, 10^5, 10^6) at
    [width] x [height] (default 320x240) on [domains] domains (default 1). *)

val direct_spheres : ?domains:int -> int -> Camlray.Scene.t
(** The spheres workload built in code, without parsing (used when
    CAMLRAY_BENCH_DIRECT is set, to skip the parse of 10^6 spheres). *)

val print : row list -> unit
(** The table and the ratios t(10^6)/t(10^3). *)

val camera_rays : Camlray.Scene.t -> width:int -> height:int -> Camlray.Ray.t array
(** A camera ray through the centre of every pixel, row by row. *)

val nearest_pass : Camlray.Scene.t -> Camlray.Ray.t array -> unit -> int
(** [nearest_pass s rays] makes its records once and returns a pass: the
    nearest hit ({!Camlray.Scene.nearest}) of every ray, the count of rays
    that hit. A pass allocates nothing. *)
