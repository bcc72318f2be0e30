open Color

(* Build an orthonormal basis around [n] (Duff et al. 2017). *)
let basis (n : Vec3.t) =
  let sign = Float.copy_sign 1. n.z in
  let a = -1. /. (sign +. n.z) in
  let b = n.x *. n.y *. a in
  ( Vec3.make (1. +. (sign *. n.x *. n.x *. a)) (sign *. b) (-.sign *. n.x),
    Vec3.make b (sign +. (n.y *. n.y *. a)) (-.n.y) )

let cosine_sample n u1 u2 =
  let r = Float.sqrt u1 and phi = 2. *. Float.pi *. u2 in
  let t, b = basis n in
  let x = r *. Float.cos phi and y = r *. Float.sin phi in
  let z = Float.sqrt (Float.max 0. (1. -. u1)) in
  Vec3.add (Vec3.add (Vec3.scale x t) (Vec3.scale y b)) (Vec3.scale z n)

(* Direct light from point, spot and parallel lights: a light of POV-Ray
   colour c gives a Lambertian surface of albedo a the radiance
   a c cos(theta), exactly POV-Ray's diffuse term. *)
let direct (s : Scene.t) p n albedo =
  Array.fold_left
    (fun acc (light : Light.t) ->
      let l, dist = Light.direction_to light p in
      let cos = Vec3.dot n l in
      if cos <= 0. then acc
      else
        let att = Light.attenuation light p in
        if att <= 0. then acc
        else
          let blocked =
            (not light.shadowless)
            && not
                 (Scene.occluders s (Ray.make p l) Ray.shadow_epsilon dist (fun _ _ ->
                      false))
          in
          if blocked then acc else madd acc (att *. cos) (mul albedo light.color))
    black s.lights

let li (s : Scene.t) sampler ~max_depth ray =
  let rec go (ray : Ray.t) depth throughput acc =
    if depth > max_depth then acc
    else
      let tmin = if depth = 0 then 0. else Ray.epsilon in
      match Scene.intersect s ray tmin infinity with
      | None -> madd acc 1. (mul throughput s.background)
      | Some hit ->
          let d = ray.dir in
          let n = if Vec3.dot hit.normal d < 0. then hit.normal else Vec3.neg hit.normal in
          let layer = List.hd hit.obj.texture in
          let f = layer.finish in
          let pig = Pigment.eval layer.pigment hit.point in
          let acc = add acc (mul throughput (mul pig.c f.emission)) in
          let albedo = scale f.diffuse pig.c in
          let kr = f.reflection.rmax in
          let acc = add acc (mul throughput (direct s hit.point n albedo)) in
          (* choose between mirror and diffuse bounce by their weights *)
          let wr = max_channel kr and wd = max_channel albedo in
          if wr +. wd <= 0. then acc
          else
            let u = Sampler.float sampler in
            let pr = wr /. (wr +. wd) in
            let throughput, dir =
              if u < pr then
                (scale (1. /. pr) (mul throughput kr), Vec3.madd d (-2. *. Vec3.dot d n) n)
              else
                ( scale (1. /. (1. -. pr)) (mul throughput albedo),
                  cosine_sample n (Sampler.float sampler) (Sampler.float sampler) )
            in
            (* emission and direct light were counted by next-event
               estimation; the background is reached by the bounce only *)
            let q = if depth >= 3 then Float.min 0.95 (max_channel throughput) else 1. in
            if Sampler.float sampler >= q then acc
            else go (Ray.make hit.point dir) (depth + 1) (scale (1. /. q) throughput) acc
  in
  go ray 0 white black

let pixel (s : Scene.t) ~width ~height ~seed ~spp ~max_depth x y =
  let side = int_of_float (Float.sqrt (float_of_int spp)) in
  let strat = side * side = spp in
  let acc = ref black in
  for k = 0 to spp - 1 do
    let sampler = Sampler.create ~seed ~pixel:((y * width) + x) ~sample:k in
    let u1 = Sampler.float sampler and u2 = Sampler.float sampler in
    let jx, jy =
      if strat then
        ((float_of_int (k mod side) +. u1) /. float_of_int side,
         (float_of_int (k / side) +. u2) /. float_of_int side)
      else (u1, u2)
    in
    let sx, sy =
      Camera.pixel_coords ~width ~height (float_of_int x +. jx) (float_of_int y +. jy)
    in
    let ray =
      Camera.ray_lens s.camera sx sy (Sampler.float sampler) (Sampler.float sampler)
    in
    acc := add !acc (li s sampler ~max_depth ray)
  done;
  scale (1. /. float_of_int spp) !acc
