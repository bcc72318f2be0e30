open Camlray

type row = {
  kind : string;
  count : int;
  parse_s : float;
  build_s : float;
  trace_s : float;  (* best of three *)
  bytes_per_prim : float;
}

let now () = Mtime.Span.to_float_ns (Mtime_clock.elapsed ()) *. 1e-9

let time f =
  let t0 = now () in
  let x = f () in
  (x, now () -. t0)

let header =
  "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
   camera { location <0, 0.6, -4> look_at 0 angle 45 }\n\
   light_source { <-5, 8, -6> color rgb 1 }\nbackground { color rgb <0.3, 0.4, 0.6> }\n"

(* n spheres in the cube [-1,1]^3, radii shrinking as n^(-1/3) *)
let sphere_text n =
  let rng = Random.State.make [| 1; n |] in
  let b = Buffer.create (n * 60) in
  Buffer.add_string b header;
  let r = 0.5 *. (float n ** (-1. /. 3.)) in
  for _ = 1 to n do
    let c () = Random.State.float rng 2. -. 1. in
    Buffer.add_string b
      (Printf.sprintf "sphere { <%.5f, %.5f, %.5f>, %.5f pigment { rgb <0.9, 0.5, 0.2> } }\n" (c ()) (c ()) (c ()) r)
  done;
  Buffer.contents b

(* BVHs are built on as many domains as the render uses *)
let par domains = if domains > 1 then Some (Render.parallel ~domains) else None

let compile ?(domains = 1) text =
  match Camlray_lang.Parse.string text with
  | Error d -> failwith (Camlray_lang.Diag.to_string d)
  | Ok sdl -> (
      match Camlray_lang.Compile.scene ?par:(par domains) sdl with
      | Ok s -> s
      | Error d -> failwith (Camlray_lang.Diag.to_string d))

(* the best of seven runs: these machines are shared and noisy, and a
   render of 10^3 objects takes some 12 ms (with three, t(10^3) moved by
   1 ms, 8%, from run to run); pixels written in place, as [camlray
   render] runs them *)
let trace ~width ~height ~domains (s : Scene.t) =
  Gc.full_major ();
  let pixel = Whitted.pixel_into s ~width ~height in
  List.fold_left Float.min infinity
    (List.init 7 (fun _ -> snd (time (fun () -> Render.image_into ~domains ~width ~height pixel))))

(* the spheres' colour, as the text workload writes it *)
let sphere_texture =
  Texture.plain (Pigment.Solid { c = Color.make 0.9 0.5 0.2; filter = 0.; transmit = 0. }) Finish.default

let direct_spheres ?(domains = 1) n =
  let base = compile header in
  let rng = Random.State.make [| 1; n |] in
  let r = 0.5 *. (float n ** (-1. /. 3.)) in
  let texture = sphere_texture in
  let objects = Array.init n (fun _ ->
      let c () = Random.State.float rng 2. -. 1. in
      let x = c () in let y = c () in let z = c () in
      Object.make ~texture (Shape.sphere (Vec3.make x y z) r)) in
  Scene.with_objects base objects (Scene.accelerate ?par:(par domains) objects)

(* n spheres on the unit sphere (a Fibonacci lattice), each of radius
   1.2 times half the lattice's spacing (as n^(-1/2)), so that they cover
   the same disc of the screen at every count, as the subdivided sphere
   mesh does: the volume's spheres leave its cube half empty at 10^3 and
   opaque at 10^6, these are opaque at every count. Built in code. *)
let shell_spheres ~width ~height ~domains n =
  let base = compile header in
  let r = 1.2 *. 0.5 *. Float.sqrt (4. *. Float.pi /. float n) in
  let texture = sphere_texture in
  let turn = Float.pi *. (3. -. Float.sqrt 5.) in
  let objects =
    Array.init n (fun i ->
        let y = 1. -. (2. *. (float i +. 0.5) /. float n) in
        let ring = Float.sqrt (1. -. (y *. y)) and th = turn *. float i in
        Object.make ~texture (Shape.sphere (Vec3.make (ring *. Float.cos th) y (ring *. Float.sin th)) r))
  in
  let accel, t_bvh = time (fun () -> Scene.accelerate ?par:(par domains) objects) in
  let s = Scene.with_objects base objects accel in
  { kind = "sphere shell"; count = n; parse_s = 0.; build_s = t_bvh; trace_s = trace ~width ~height ~domains s;
    bytes_per_prim = nan }

let spheres ~width ~height ~domains n =
  let s, t_all =
    if Sys.getenv_opt "CAMLRAY_BENCH_DIRECT" <> None then time (fun () -> direct_spheres ~domains n)
    else
      let text = sphere_text n in
      time (fun () -> compile ~domains text)
  in
  (* the compile step includes the scene BVH: time it alone and subtract *)
  let _, t_bvh = time (fun () -> Scene.accelerate ?par:(par domains) s.objects) in
  { kind = "spheres"; count = n; parse_s = Float.max 0. (t_all -. t_bvh); build_s = t_bvh;
    trace_s = trace ~width ~height ~domains s; bytes_per_prim = nan }

(* A subdivided sphere (latitude/longitude grid) or a heightfield terrain of
   about n triangles, filling the same region as the spheres. *)
let mesh_data kind n =
  let k = max 2 (int_of_float (Float.sqrt (float n /. 2.))) in
  let verts = Float.Array.create (3 * (k + 1) * (k + 1)) in
  let set i x y z = Float.Array.set verts (3 * i) x; Float.Array.set verts ((3 * i) + 1) y; Float.Array.set verts ((3 * i) + 2) z in
  for i = 0 to k do
    for j = 0 to k do
      let u = float i /. float k and v = float j /. float k in
      let idx = (i * (k + 1)) + j in
      match kind with
      | `Sphere ->
          let th = Float.pi *. u and ph = 2. *. Float.pi *. v in
          set idx (Float.sin th *. Float.cos ph) (Float.cos th) (Float.sin th *. Float.sin ph)
      | `Terrain ->
          let x = (2. *. u) -. 1. and z = (2. *. v) -. 1. in
          let y = 0.3 *. (Float.sin (7. *. x) *. Float.cos (5. *. z) +. (0.3 *. Float.sin (23. *. x *. z))) in
          set idx x y z
    done
  done;
  let faces = Array.make (6 * k * k) 0 in
  for i = 0 to k - 1 do
    for j = 0 to k - 1 do
      let a = (i * (k + 1)) + j in
      let b = a + 1 and c = a + k + 1 and d = a + k + 2 in
      let o = 6 * ((i * k) + j) in
      faces.(o) <- a; faces.(o + 1) <- b; faces.(o + 2) <- c;
      faces.(o + 3) <- b; faces.(o + 4) <- d; faces.(o + 5) <- c
    done
  done;
  (verts, faces)

let mesh ~width ~height ~domains kind n =
  let verts, faces = mesh_data kind n in
  let m, t_build =
    time (fun () -> Mesh.make ~par:(par domains) ~verts ~normals:(Float.Array.create 0) ~faces ~normal_faces:[||] ~inside_vector:None ())
  in
  let tris = Mesh.triangles m in
  let texture = Texture.plain (Pigment.Solid { c = Color.make 0.3 0.7 0.4; filter = 0.; transmit = 0. }) Finish.default in
  let base = compile header in
  let objects = [| Object.make ~texture (Shape.Mesh m) |] in
  let s = Scene.with_objects base objects (Scene.accelerate ?par:(par domains) objects) in
  { kind = (match kind with `Sphere -> "sphere mesh" | `Terrain -> "terrain mesh"); count = tris;
    parse_s = 0.; build_s = t_build; trace_s = trace ~width ~height ~domains s;
    bytes_per_prim = float (Mesh.bytes m) /. float tris }

let run ?(sizes = [ 10; 1000; 100_000; 1_000_000 ]) ?(width = 320) ?(height = 240) ?(domains = 1) () =
  List.concat_map
    (fun n ->
      [ spheres ~width ~height ~domains n; shell_spheres ~width ~height ~domains n;
        mesh ~width ~height ~domains `Sphere n; mesh ~width ~height ~domains `Terrain n ])
    sizes

let print rows =
  Printf.printf "%-14s %9s %9s %9s %9s %11s\n" "workload" "objects" "parse s" "build s" "trace s" "bytes/prim";
  List.iter
    (fun r ->
      Printf.printf "%-14s %9d %9.3f %9.3f %9.3f %11s\n%!" r.kind r.count r.parse_s r.build_s r.trace_s
        (if Float.is_nan r.bytes_per_prim then "-" else Printf.sprintf "%.0f" r.bytes_per_prim))
    rows;
  let kinds = List.sort_uniq compare (List.map (fun r -> r.kind) rows) in
  List.iter
    (fun k ->
      let of_kind = List.filter (fun r -> r.kind = k) rows in
      let near n = List.fold_left (fun acc r -> match acc with
          | Some a when abs (a.count - n) <= abs (r.count - n) -> acc | _ -> Some r) None of_kind in
      match (near 1000, near 1_000_000) with
      | Some a, Some b when b.count > 100 * a.count ->
          Printf.printf "%s: t(%d)/t(%d) = %.2f\n" k b.count a.count (b.trace_s /. a.trace_s)
      | _ -> ())
    kinds

(* The traversal and intersection kernel alone (bench/alloc and the
   allocation test): a camera ray through every pixel's centre, and a pass
   of nearest hits over them with records made once. *)
let camera_rays (s : Scene.t) ~width ~height =
  Array.init (width * height) (fun i ->
      let sx, sy = Camera.pixel_coords ~width ~height (float (i mod width) +. 0.5) (float (i / width) +. 0.5) in
      Camera.ray s.camera sx sy)

let nearest_pass (s : Scene.t) rays =
  let r = Ray.scratch () and h = Hit.create infinity and f = Object.found s.objects.(0) in
  fun () ->
    let hits = ref 0 in
    for i = 0 to Array.length rays - 1 do
      Ray.load r (Array.unsafe_get rays i);
      h.t <- infinity;
      if Scene.nearest s r 0. h f then incr hits
    done;
    !hits
