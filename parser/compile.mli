(** The compile step: the evaluated scene description becomes the
    renderer's {!Camlray.Scene.t}. POV-Ray's camera placement rules, its
    gamma rules and default textures are applied here; semantic errors
    come from here, located. *)

val camera : Loc.t -> Sdl.camera_item list -> Camlray.Camera.t
(** POV-Ray's camera model (the camera at the location given, for its
    warnings): keywords applied in its fixed order (type, up/right, angle,
    look_at, orthographic sizing, then transforms in written order). *)

val mesh_camera_at : Sdl.scene -> Loc.t option
(** Where the camera in force (the scene's last) is made a
    [mesh_camera], if it is: for the renderers that refuse one. *)

val scene : ?par:(int -> (int -> unit) -> unit) -> Sdl.scene -> (Camlray.Scene.t, Diag.t) result
(** [par]: build the BVHs of large meshes and of the scene in parallel
    ({!Camlray.Render.parallel}); the trees are the same as without. *)

val standalone : Sdl.obj -> Camlray.Object.t option
(** One object compiled on its own, while the scene is read ([None] for
    an object that is only a light); its lights are dropped. Errors raise
    {!Diag.Error}. *)
