type t = {
  shape : Shape.t;
  xform : Transform.t;
  texture : Texture.t;
  interior : Interior.t;
  no_shadow : bool;
}

let make ?(xform = Transform.identity) ?(texture = Texture.default)
    ?(interior = Interior.default) ?(no_shadow = false) shape =
  { shape; xform; texture; interior; no_shadow }

let intersect o (r : Ray.t) tmin tmax =
  if Transform.is_identity o.xform then Shape.intersect o.shape r tmin tmax
  else
    let r' =
      Ray.make (Transform.inv_point o.xform r.origin) (Transform.inv_vector o.xform r.dir)
    in
    Shape.intersect o.shape r' tmin tmax

let normal o p =
  if Transform.is_identity o.xform then Shape.normal o.shape p
  else
    let n = Shape.normal o.shape (Transform.inv_point o.xform p) in
    Vec3.normalize (Transform.normal o.xform n)

let inside o p = Shape.inside o.shape (Transform.inv_point o.xform p)

let bounds o =
  match Shape.bounds o.shape with
  | None -> None
  | Some (lo, hi) ->
      let corners =
        List.init 8 (fun i ->
            Transform.point o.xform
              (Vec3.make
                 (if i land 1 = 0 then lo.x else hi.x)
                 (if i land 2 = 0 then lo.y else hi.y)
                 (if i land 4 = 0 then lo.z else hi.z)))
      in
      let first = List.hd corners in
      Some
        ( List.fold_left Vec3.min first corners,
          List.fold_left Vec3.max first corners )
