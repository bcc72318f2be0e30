(** Scene objects: a shape placed by a transform, with its texture and
    interior. The transform's inverse is stored once (in [Transform.t]). *)

type t = {
  shape : Shape.t;
  xform : Transform.t;  (** object space to world space *)
  texture : Texture.t;
  interior : Interior.t;
  no_shadow : bool;
}

val make :
  ?xform:Transform.t -> ?texture:Texture.t -> ?interior:Interior.t ->
  ?no_shadow:bool -> Shape.t -> t

val intersect : t -> Ray.t -> float -> float -> float
(** Nearest hit distance in [(tmin, tmax)] along a world ray, or
    [infinity]. *)

val normal : t -> Vec3.t -> Vec3.t
(** Outward unit world-space normal at a world point on the surface. *)

val inside : t -> Vec3.t -> bool

val bounds : t -> (Vec3.t * Vec3.t) option
(** World-space axis-aligned bounds; [None] when infinite. *)
