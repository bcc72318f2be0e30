open Camlray

(* One record for equal plain textures (one layer, a plain colour, no
   normal): 10^6 spheres each written with the same pigment and finish
   share one texture instead of 10^6 copies, from the moment each is
   read (some 270 bytes a sphere less to hold until the scene is
   compiled) to the render (shading read the copies from all over memory:
   10^6 spheres at 320x240 traced in 0.248 s, 0.132 s shared). The key is
   plain data (colours, floats, booleans); textures are values, so
   sharing changes nothing else. *)
let shared : (Color.rgbft * Finish.t, Texture.t) Hashtbl.t = Hashtbl.create 16

let share_texture (t : Texture.t) =
  match t with
  | [ { pigment = Pigment.Solid c; normal = None; tmap = None; finish; uv_texture = false } ] -> (
      let k = (c, finish) in
      match Hashtbl.find_opt shared k with
      | Some t' -> t'
      | None ->
          Hashtbl.add shared k t;
          t)
  | _ -> t

let forget_textures () = Hashtbl.reset shared

let obj loc shape ms =
  Budget.parsed loc;
  let o =
    { Sdl.loc; shape; xform = Transform.identity; texture = None; interior = None; no_shadow = false;
      hollow = false; flags = 0; inner = None; photon = Photon.none }
  in
  let o = List.fold_left (fun o f -> f o) o ms in
  match o.texture with
  | Some t -> { o with texture = Some (share_texture t) }
  | None -> o

let set_open loc (o : Sdl.obj) =
  match o.shape with
  | Sdl.Cone c -> { o with shape = Sdl.Cone { c with open_ = true } }
  | Sdl.Prism p -> { o with shape = Sdl.Prism { p with no_caps = true } }
  | Sdl.Sor s -> { o with shape = Sdl.Sor { s with sor_open = true } }
  | Sdl.Isosurface i -> { o with shape = Sdl.Isosurface { i with iso_open = true } }
  | _ -> Diag.warning loc "'open' only applies to cylinders, cones, prisms and sors; ignored"; o

let wrap (o : Sdl.obj) shape =
  { o with shape; xform = Transform.identity; texture = o.texture; interior = o.interior; no_shadow = false; flags = 0 }

let strip (o : Sdl.obj) = { o with texture = None; interior = None }
let inverse (o : Sdl.obj) = wrap o (Sdl.Inverse (strip o))
let clipped clips (o : Sdl.obj) = wrap o (Sdl.Clipped (strip o, clips))
let bounded bounds (o : Sdl.obj) = wrap o (Sdl.Bounded (strip o, bounds))

(* [bounded_by { clipped_by }], [clipped_by { bounded_by }]: the other
   list, moved by what came after it *)
let bound_by_clip loc (o : Sdl.obj) =
  match o.shape with
  | Sdl.Clipped (_, cs) -> bounded (List.map (Sdl.transform_obj o.xform) cs) o
  | _ -> Diag.error loc "bounded_by { clipped_by } needs a clipped_by before it"

let clip_by_bound loc (o : Sdl.obj) =
  match o.shape with
  | Sdl.Bounded (_, bs) -> clipped (List.map (Sdl.transform_obj o.xform) bs) o
  | _ -> Diag.error loc "clipped_by { bounded_by } needs a bounded_by before it"

let algebraic loc what order (v : Value.t) =
  let need = Algebraic.terms order in
  match v with
  | Value.Vector a when Array.length a = need -> Sdl.Algebraic { order; coef = Array.copy a; quadric = false }
  | Value.Vector a -> Diag.error loc "a %s needs %d coefficients, this one has %d" what need (Array.length a)
  | v -> Diag.error loc "a %s needs a vector of %d coefficients, found %s" what need (Value.type_name v)

let poly order_loc loc order v =
  let n = Value.to_float order_loc order in
  if Float.of_int (Float.to_int n) <> n || n < 2. || n > float Algebraic.max_order then
    Diag.error order_loc "a poly's order is a whole number from 2 to %d, found %g" Algebraic.max_order n;
  algebraic loc (Printf.sprintf "poly of order %d" (Float.to_int n)) (Float.to_int n) v

(* fonts read in this process, by path *)
let fonts : (string, Ttf.t) Hashtbl.t = Hashtbl.create 4

(* The characters of a text's string by global_settings' charset, as
   POV-Ray 3.7 reads them: ascii (its default) keeps bytes below 128 and
   puts a space for each other byte, with a warning; utf8 decodes; sys
   POV-Ray cannot convert on this platform (its error, for any text) *)
let text_codes loc s =
  match Defaults.charset () with
  | `Sys -> Diag.error loc "charset sys: system-specific text cannot be converted here (POV-Ray's error too): use utf8"
  | `Ascii ->
      let codes = Array.init (String.length s) (fun i -> Char.code s.[i]) in
      if Array.exists (fun c -> c >= 128) codes then begin
        Diag.warning loc "non-ASCII characters replaced by spaces, as POV-Ray does (charset ascii): add charset utf8 to global_settings";
        Array.map (fun c -> if c >= 128 then 32 else c) codes
      end
      else codes
  | `Utf8 ->
      let n = String.length s in
      let rec go i acc =
        if i >= n then Array.of_list (List.rev acc)
        else
          let d = String.get_utf_8_uchar s i in
          if not (Uchar.utf_decode_is_valid d) then
            Diag.error loc "this text's string is not valid UTF-8 (byte %d), as charset utf8 requires" (i + 1)
          else go (i + Uchar.utf_decode_length d) (Uchar.to_int (Uchar.utf_decode_uchar d) :: acc)
      in
      go 0 []

let text loc font chars thickness offset =
  (* POV-Ray also tries the name with .ttf added *)
  let path =
    match Defaults.find_file loc font with
    | Some p -> p
    | None -> (
        match Defaults.find_file loc (font ^ ".ttf") with
        | Some p -> p
        | None -> Diag.error loc "cannot find font %s (looked in the scene's folder and the include path)" font)
  in
  let f =
    match Hashtbl.find_opt fonts path with
    | Some f -> f
    | None -> (
        match Ttf.read path with
        | f ->
            Hashtbl.replace fonts path f;
            f
        | exception Failure m -> Diag.error loc "cannot read font %s" m)
  in
  if thickness < 0. then Diag.error loc "a text's thickness must be >= 0, found %g" thickness;
  Sdl.Text { font; chars; thickness; offset; glyphs = Text.make_codes f (text_codes loc chars) ~thickness ~offset }

(* a prism's or lathe's spline and sweep words, its counted 2-D points *)
let spline_words loc what kinds =
  let spline = ref Prism.Linear and sweep = ref Prism.Linear_sweep in
  List.iter
    (function
      | "linear_spline" -> spline := Prism.Linear
      | "quadratic_spline" -> spline := Prism.Quadratic
      | "cubic_spline" -> spline := Prism.Cubic
      | "bezier_spline" -> spline := Prism.Bezier
      | "linear_sweep" when what = "prism" -> sweep := Prism.Linear_sweep
      | "conic_sweep" when what = "prism" -> sweep := Prism.Conic_sweep
      | k -> Diag.error loc "%s is not a %s's spline%s" k what (if what = "prism" then " or sweep" else ""))
    kinds;
  (!spline, !sweep)

let points_2d what (nloc, n) pts =
  if List.length pts <> n then
    Diag.error nloc "this %s announces %d points and lists %d" what n (List.length pts);
  let point (l, v) =
    match v with
    | Value.Float f -> (f, f)
    | Value.Vector a when Array.length a >= 2 -> (a.(0), a.(1))
    | v -> Diag.error l "a %s's point is a 2-vector, found %s" what (Value.type_name v)
  in
  Array.of_list (List.map point pts)

let sor loc count pts ~open_ =
  let points = points_2d "sor" count pts in
  (match Sor.make ~open_ points with Ok _ -> () | Error e -> Diag.error loc "sor: %s" e);
  Sdl.Sor { points; sor_open = open_ }

let lathe loc kinds count pts =
  let spline, _ = spline_words loc "lathe" kinds in
  let points = points_2d "lathe" count pts in
  (match Lathe.make spline points with Ok _ -> () | Error e -> Diag.error loc "lathe: %s" e);
  Sdl.Lathe (spline, points)

let prism loc kinds height1 height2 count pts =
  let spline, sweep = spline_words loc "prism" kinds in
  let points = points_2d "prism" count pts in
  (* checked now, for a located message *)
  (match Prism.make spline sweep height1 height2 points with
   | Ok _ -> ()
   | Error e -> Diag.error loc "prism: %s" e);
  Sdl.Prism { spline; sweep; height1; height2; points; no_caps = false }

let polygon loc (nloc, n) pts =
  if List.length pts <> n then Diag.error nloc "this polygon announces %d points and lists %d" n (List.length pts);
  let points = Array.of_list (List.map (fun (l, v) -> Value.to_vec3 l v) pts) in
  (* checked now, for a located message *)
  (match Polygon.make points with
   | Ok (_, true) -> ()
   | Ok (_, false) -> Diag.warning loc "polygon not closed (its last point is not its outline's first): closed"
   | Error e -> Diag.error loc "polygon: %s" e);
  Sdl.Polygon points

(* height_field: its source, options as the grammar reads them *)
type hf_source = Hf_file of Loc.t * string option * string | Hf_fn of Loc.t * int * int * Fn.t * string option
type hf_option = Hf_smooth | Hf_water of Loc.t * float

let height_field src opts =
  let smooth = List.mem Hf_smooth opts in
  let water = List.fold_left (fun w o -> match o with Hf_water (_, x) -> x | Hf_smooth -> w) 0. opts in
  List.iter
    (function
      | Hf_water (l, x) when x < 0. || x > 1. -> Diag.warning l (Printf.sprintf "water_level %g is outside 0 .. 1" x)
      | _ -> ())
    opts;
  let (w, h, v), source =
    match src with
    | Hf_file (loc, kind, file) -> (
        (match kind with
         | Some ("tga" | "iff" | "sys" | "tiff" | "bmp" | "exr" | "hdr" as k) ->
             Diag.error loc "%s (a height_field file type) is not supported by camlray: png, jpeg, gif, pot, pgm and ppm are" k
         | _ -> ());
        let path =
          match Defaults.find_file loc file with
          | Some p -> p
          | None -> Diag.error loc "cannot find height_field image %s (looked in the scene's folder and the include path)" file
        in
        match Hf_image.read ~pot:(kind = Some "pot") path with
        | im -> ((im.w, im.h, im.v), Sdl.Hf_file (kind, file))
        | exception Failure m -> Diag.error loc "cannot read height_field image %s: %s" file m)
    | Hf_fn (loc, w, h, f, text) ->
        if w < 2 || h < 2 then Diag.error loc "a height_field function needs at least 2 x 2 points, found %d x %d" w h;
        if w * h > 1 lsl 26 then Diag.error loc "a height_field function of %d x %d points is too large" w h;
        (* Make_Pattern_Image: pixel (j, i) is the function at <j/(w-1), i/(h-1), 0> *)
        let at =
          if Fn.is_vector f then fun x y ->
            let c = Fn.call_vector loc f [ x; y; 0. ] in
            let g k = if k < Array.length c then c.(k) else 0. in
            Hf_image.of_color (g 0) (g 1) (g 2)
          else
            match Fn.eval3 f with
            | e -> fun x y -> Hf_image.of_float (e x y 0.)
            | exception Invalid_argument m -> Diag.error loc "height_field function: %s" m
        in
        let v = Array.make (w * h) 0 in
        for i = 0 to h - 1 do
          for j = 0 to w - 1 do
            v.((i * w) + j) <- at (float j /. float (w - 1)) (float i /. float (h - 1))
          done
        done;
        ((w, h, v), Sdl.Hf_function (w, h, text))
  in
  (match src with
   | Hf_file (loc, _, file) when w < 2 || h < 2 ->
       Diag.error loc "height_field image %s is %d x %d: at least 2 x 2 pixels are needed" file w h
   | _ -> ());
  Sdl.Height_field { source; smooth; water; field = Height_field.make ~width:w ~depth:h ~heights:v ~smooth ~water }
type iso_item =
  | Iso_container of Isosurface.container
  | Iso_threshold of float
  | Iso_accuracy of Loc.t * float
  | Iso_max_gradient of Loc.t * float
  | Iso_evaluate of Loc.t * (float * float * float)
  | Iso_max_trace of Loc.t * int
  | Iso_mod of (Sdl.obj -> Sdl.obj)

(* POV-Ray takes a negative radius as its size (functions.inc's own
   sample writes sphere { 0, -3.3 }) *)
let iso_sphere _loc c r = Isosurface.Sphere (c, Float.abs r)

(* POV-Ray's defaults: contained_by { box { -1, 1 } }, threshold 0,
   accuracy 0.001, max_gradient 1.1, max_trace 1 *)
let isosurface loc floc (f : Fn.t) items =
  (match Fn.unsupported f with Some u -> Diag.error floc "%s" u | None -> ());
  if Fn.is_vector f then Diag.error floc "an isosurface's function must return a float, not a vector";
  if Fn.arity f <> 3 then
    Diag.error floc "an isosurface's function takes 3 parameters (x, y, z), this one takes %d" (Fn.arity f);
  let iso =
    { Sdl.fn = f; container = Isosurface.Box (Vec3.make (-1.) (-1.) (-1.), Vec3.make 1. 1. 1.); threshold = 0.;
      accuracy = 0.001; max_gradient = 1.1; evaluate = None; iso_open = false; max_trace = 1 }
  in
  let o = { Sdl.loc; shape = Sdl.Isosurface iso; xform = Transform.identity; texture = None; interior = None;
            no_shadow = false; hollow = false; flags = 0; inner = None; photon = Photon.none } in
  List.fold_left
    (fun (o : Sdl.obj) item ->
      let set g = match o.shape with Sdl.Isosurface i -> { o with shape = Sdl.Isosurface (g i) } | _ -> o in
      match item with
      | Iso_container c -> set (fun i -> { i with container = c })
      | Iso_threshold x -> set (fun i -> { i with threshold = x })
      | Iso_accuracy (l, x) ->
          if not (x > 0.) then Diag.error l "an isosurface's accuracy must be positive, found %g" x;
          set (fun i -> { i with accuracy = x })
      | Iso_max_gradient (l, x) ->
          if not (x > 0.) then Diag.error l "an isosurface's max_gradient must be positive, found %g" x;
          set (fun i -> { i with max_gradient = x })
      | Iso_evaluate (l, e) ->
          Diag.warning l
            "evaluate is read and not used: camlray searches with max_gradient (POV-Ray's estimate \
             changes with the order rays are traced)";
          set (fun i -> { i with evaluate = Some e })
      | Iso_max_trace (l, n) ->
          if n < 1 then Diag.error l "an isosurface's max_trace must be at least 1, found %d" n;
          set (fun i -> { i with max_trace = n })
      | Iso_mod m -> m o)
    o items

let julia loc c words =
  let jc =
    match c with
    | Value.Vector [| a; b; c; d |] -> [| a; b; c; d |]
    | v -> Diag.error loc "a julia_fractal needs a 4-vector <a, b, c, d> first, found %s" (Value.type_name v)
  in
  (* POV-Ray's defaults: quaternion, sqr, max_iteration 20, precision 20 (measured) *)
  let hyper, cube, max_iteration, precision =
    List.fold_left
      (fun (h, cube, n, p) w ->
        match w with
        | `Sqr -> (h, false, n, p)
        | `Cube -> (h, true, n, p)
        | `Quat -> (None, cube, n, p)
        | `Hyper l -> (Some l, cube, n, p)
        | `Iter (l, v) ->
            let n = Value.to_int l v in
            if n < 1 then Diag.error l "a julia_fractal's max_iteration must be at least 1, found %d" n;
            (h, cube, n, p)
        | `Prec (l, v) ->
            let p = Value.to_float l v in
            if not (p > 0.) then Diag.error l "a julia_fractal's precision must be positive, found %g" p;
            (h, cube, n, p)
        | `Slice (l, v, d) -> (
            match v with
            | Value.Vector [| 0.; 0.; 0.; w |] when w > 0. && Value.to_float l d = 0. -> (h, cube, n, p)
            | _ -> Diag.error l "slice (other than <0, 0, 0, 1>, 0) is not supported by camlray"))
      (None, false, 20, 20.) words
  in
  (match hyper with
  | Some l when cube -> Diag.error l "a hypercomplex julia_fractal takes sqr only: cube is not supported by camlray"
  | _ -> ());
  Sdl.Julia { jc; hypercomplex = hyper <> None; cube; max_iteration; precision }

(* text { internal N ... }: POV-Ray 3.7's four built-in fonts are the
   TrueType files it installs beside its includes (rendered identical) *)
let internal_font loc n =
  match n with
  | 0 -> "povlogo.ttf"
  | 1 -> "timrom.ttf"
  | 2 -> "cyrvetic.ttf"
  | 3 -> "crystal.ttf"
  | n -> Diag.error loc "POV-Ray's internal fonts are 0 to 3, found %d" n

let superellipsoid loc v =
  match v with
  | Value.Vector [| e; n |] ->
      if not (e > 0. && n > 0.) then Diag.error loc "a superellipsoid's exponents must be positive, found <%g, %g>" e n;
      Sdl.Superellipsoid (e, n)
  | v -> Diag.error loc "a superellipsoid needs <e, n>, found %s" (Value.type_name v)

let blob_sphere loc center radius strength =
  if not (radius > 0.) then Diag.error loc "a blob component's radius must be positive, found %g" radius;
  Blob.Sphere { center; radius; strength }

let blob_cylinder loc a b radius strength =
  if not (radius > 0.) then Diag.error loc "a blob component's radius must be positive, found %g" radius;
  if Vec3.dist a b = 0. then Diag.error loc "a blob cylinder's two end points must differ";
  Blob.Cylinder { a; b; radius; strength }

(* A blob component's transformation: moves, turns and uniform scales
   move it (a sphere stays a sphere, as in POV-Ray); anything else places
   it, its field taken in its own space *)
let blob_moved t (c : Blob.component) =
  if Transform.is_identity t then c
  else
    let ax = Transform.vector t Vec3.unit_x and ay = Transform.vector t Vec3.unit_y
    and az = Transform.vector t Vec3.unit_z in
    let k = Vec3.length ax in
    let close a b = Float.abs (a -. b) <= 1e-9 *. Float.max 1. (Float.abs b) in
    let even =
      close (Vec3.length ay) k && close (Vec3.length az) k && close (Vec3.dot ax ay) 0.
      && close (Vec3.dot ax az) 0. && close (Vec3.dot ay az) 0.
    in
    match c with
    | Blob.Sphere { center; radius; strength } when even ->
        Blob.Sphere { center = Transform.point t center; radius = radius *. k; strength }
    | Blob.Cylinder { a; b; radius; strength } when even ->
        Blob.Cylinder { a = Transform.point t a; b = Transform.point t b; radius = radius *. k; strength }
    | c -> Blob.place t c

(* The modifiers are applied, in order, to a stand-in object: its
   transform is the component's, its texture the component's own (moved
   by the transformations written after it, as an object's) *)
let blob_component loc ms comp =
  let o =
    { Sdl.loc; shape = Sdl.Sphere (Vec3.zero, 1.); xform = Transform.identity; texture = None; interior = None;
      no_shadow = false; hollow = false; flags = 0; inner = None; photon = Photon.none }
  in
  let o = List.fold_left (fun o f -> f o) o ms in
  { Sdl.comp = blob_moved o.xform comp; ctex = o.texture }

(* A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J, in
   the terms of an order-2 poly: x^2, xy, xz, x, y^2, yz, y, z^2, z, 1 *)
let quadric (abc : Vec3.t) (def : Vec3.t) (ghi : Vec3.t) j =
  Sdl.Algebraic
    { order = 2; coef = [| abc.x; def.x; def.y; ghi.x; abc.y; def.z; ghi.y; abc.z; ghi.z; j |]; quadric = true }

type mesh_tri = { p : Vec3.t array; uv : float array option; tex : Texture.t option }

let mesh_triangle _loc p uv tex =
  let uv =
    Option.map
      (fun l ->
        Array.concat
          (List.map
             (fun (loc, v) ->
               match v with
               | Value.Vector [| u; w |] -> [| u; w |]
               | Value.Float u -> [| u; u |]
               | v -> Diag.error loc "expected a uv vector <u, v>, found %s" (Value.type_name v))
             l))
      uv
  in
  { p; uv; tex }

let fa_of_vecs (vs : Vec3.t list) =
  let a = Float.Array.create (3 * List.length vs) in
  List.iteri (fun i (v : Vec3.t) ->
      Float.Array.set a (3 * i) v.x; Float.Array.set a ((3 * i) + 1) v.y; Float.Array.set a ((3 * i) + 2) v.z) vs;
  a

let mesh _loc tris =
  let tris = Array.of_list tris in
  let n = Array.length tris in
  let smooth = Array.exists (fun t -> Array.length t.p = 6) tris in
  let verts = ref [] and normals = ref [] in
  Array.iter (fun t ->
      if Array.length t.p = 6 then (
        verts := t.p.(4) :: t.p.(2) :: t.p.(0) :: !verts;
        normals := t.p.(5) :: t.p.(3) :: t.p.(1) :: !normals)
      else (
        verts := t.p.(2) :: t.p.(1) :: t.p.(0) :: !verts;
        if smooth then normals := Vec3.zero :: Vec3.zero :: Vec3.zero :: !normals)) tris;
  let faces = Array.init (3 * n) Fun.id in
  let normal_faces =
    if smooth then Array.init (3 * n) (fun i -> if Array.length tris.(i / 3).p = 6 then i else -1) else [||]
  in
  (* zero normals make a smooth triangle flat *)
  let normals = List.rev !normals in
  let normal_faces =
    let na = Array.of_list normals in
    Array.mapi (fun i k -> if k >= 0 && Vec3.length na.(k) = 0. then (ignore i; -1) else k) normal_faces
  in
  let normal_faces =
    Array.mapi (fun i k -> let b = 3 * (i / 3) in
      if normal_faces.(b) < 0 || normal_faces.(b + 1) < 0 || normal_faces.(b + 2) < 0 then -1 else k) normal_faces
  in
  (* triangle { A, B, C uv_vectors UA, UB, UC }: the corners' uv, in
     order (<0, 0> for a triangle without them) *)
  let uvs, uv_faces =
    if Array.for_all (fun t -> t.uv = None) tris then (Float.Array.create 0, [||])
    else
      ( Float.Array.of_list
          (List.concat_map (fun t -> Array.to_list (Option.value t.uv ~default:(Array.make 6 0.))) (Array.to_list tris)),
        Array.init (3 * n) Fun.id )
  in
  let textures = List.filter_map (fun t -> t.tex) (Array.to_list tris) in
  let face_textures =
    if textures = [] then [||]
    else
      let k = ref (-1) in
      Array.map (fun t -> match t.tex with Some _ -> incr k; !k | None -> -1) tris
  in
  Sdl.Mesh
    { verts = fa_of_vecs (List.rev !verts); normals = fa_of_vecs normals; faces; normal_faces;
      face_textures; textures = Array.of_list textures; inside_vector = None; uvs; uv_faces }

(* POV-Ray's bicubic_patch: the Bezier patch of 16 control points (four
   rows of four, u along a row, v down the rows), cut into 2^u_steps x
   2^v_steps cells of two triangles each, with the patch's own normals
   at their corners. POV-Ray subdivides the same way (down to those
   steps, sooner where flatness allows: camlray always goes down to
   them) and takes the normal at a hit from the patch. *)
let bicubic_patch loc ~u_steps ~v_steps (pts : Vec3.t array) =
  if Array.length pts <> 16 then
    Diag.error loc "a bicubic_patch needs 16 control points, found %d" (Array.length pts);
  let check what n =
    if n < 0 || n > 10 then Diag.error loc "%s goes from 0 to 10, found %d" what n
  in
  check "u_steps" u_steps;
  check "v_steps" v_steps;
  let nu = 1 lsl u_steps and nv = 1 lsl v_steps in
  let bern t = let s = 1. -. t in [| s *. s *. s; 3. *. t *. s *. s; 3. *. t *. t *. s; t *. t *. t |] in
  let dbern t =
    let s = 1. -. t in
    [| -3. *. s *. s; (3. *. s *. s) -. (6. *. t *. s); (6. *. t *. s) -. (3. *. t *. t); 3. *. t *. t |]
  in
  let sum wu wv =
    let x = ref 0. and y = ref 0. and z = ref 0. in
    for i = 0 to 3 do
      for j = 0 to 3 do
        let w = wv.(i) *. wu.(j) and (p : Vec3.t) = pts.((4 * i) + j) in
        x := !x +. (w *. p.x);
        y := !y +. (w *. p.y);
        z := !z +. (w *. p.z)
      done
    done;
    Vec3.make !x !y !z
  in
  let normal u v =
    let n u v = Vec3.cross (sum (dbern u) (bern v)) (sum (bern u) (dbern v)) in
    let m = n u v in
    if Vec3.length m > 1e-12 then Vec3.normalize m
    else
      (* a corner where an edge collapses: the normal just inside *)
      let e = 1e-4 in
      let m = n (if u > 0.5 then u -. e else u +. e) (if v > 0.5 then v -. e else v +. e) in
      if Vec3.length m > 0. then Vec3.normalize m else Vec3.zero
  in
  let verts = Float.Array.make (3 * (nu + 1) * (nv + 1)) 0. in
  (* the patch's own parameters at the grid's points: its uv *)
  let uvs = Float.Array.make (2 * (nu + 1) * (nv + 1)) 0. in
  let normals = Float.Array.make (3 * (nu + 1) * (nv + 1)) 0. in
  for i = 0 to nv do
    for j = 0 to nu do
      let u = float j /. float nu and v = float i /. float nv in
      let k = 3 * ((i * (nu + 1)) + j) in
      let p = sum (bern u) (bern v) and n = normal u v in
      Float.Array.set uvs (2 * ((i * (nu + 1)) + j)) u;
      Float.Array.set uvs ((2 * ((i * (nu + 1)) + j)) + 1) v;
      Float.Array.set verts k p.x; Float.Array.set verts (k + 1) p.y; Float.Array.set verts (k + 2) p.z;
      Float.Array.set normals k n.x; Float.Array.set normals (k + 1) n.y; Float.Array.set normals (k + 2) n.z
    done
  done;
  let vert k = Vec3.make (Float.Array.get verts (3 * k)) (Float.Array.get verts ((3 * k) + 1)) (Float.Array.get verts ((3 * k) + 2)) in
  (* the cells' two triangles, leaving out those an edge collapses to a
     line (a patch's pole) *)
  let faces = ref [] in
  let add a b c =
    let pa = vert a in
    let area = Vec3.length (Vec3.cross (Vec3.sub (vert b) pa) (Vec3.sub (vert c) pa)) in
    if area > 1e-14 then faces := c :: b :: a :: !faces
  in
  for i = 0 to nv - 1 do
    for j = 0 to nu - 1 do
      let k r c = (r * (nu + 1)) + c in
      add (k i j) (k i (j + 1)) (k (i + 1) (j + 1));
      add (k i j) (k (i + 1) (j + 1)) (k (i + 1) j)
    done
  done;
  let faces = Array.of_list (List.rev !faces) in
  if Array.length faces = 0 then Diag.error loc "this bicubic_patch is flat to a line or a point";
  Sdl.Mesh
    { verts; normals; faces; normal_faces = Array.copy faces; face_textures = [||]; textures = [||];
      inside_vector = None; uvs; uv_faces = Array.copy faces }

type mesh2_block =
  | Verts of Float.Array.t  (* x y z of each vertex *)
  | Normals of Float.Array.t
  | Faces of Loc.t * int array * int array  (* 3 indices per face; texture index per face *)
  | Uvs of Float.Array.t  (* u v of each uv_vectors entry *)
  | Uv_faces of Loc.t * int array  (* 3 uv indices per face *)
  | Nfaces of Loc.t * int array
  | Textures of Texture.t list
  | Ignored

(* A block's items as the parser reads them, kept flat: a mesh's 10^5
   items are not 10^5 records outliving collections. Each item is written
   into the block's store at its index, and the parser's value is the
   store and how many items it holds: when the parser runs an action
   ahead ([acceptable], reading a directive inside a declaration), the
   item it adds is written again, the same, at the same index when the
   parse gets there, and one it never gets to is past the count. Where
   each item stands is kept as the numbers of its two positions; its
   location is made only for a message. *)
type store = {
  mutable arity : Bytes.t;  (** per item: 0 a float, 1..254 a vector's length, 255 anything else *)
  mutable nums : Float.Array.t;  (** the floats and vectors' components, item after item *)
  mutable pos : int array;  (** 6 per item: start line, bol, cnum, stop line, bol, cnum *)
  mutable files : (int * string) list;
      (** (first item, file) where the items' file changes, latest first *)
  mutable others : (int * Value.t) list;  (** the items of arity 255 *)
}

type items = { store : store; count : int; used : int (** floats in [nums] *) }

let items () =
  { store = { arity = Bytes.create 16; nums = Float.Array.create 64; pos = Array.make 96 0; files = [];
              others = [] };
    count = 0; used = 0 }

let add_item { store = b; count = i; used } (s : Lexing.position) (e : Lexing.position) (v : Value.t) =
  if i >= Bytes.length b.arity then begin
    let a = Bytes.create (2 * (i + 1)) in
    Bytes.blit b.arity 0 a 0 (Bytes.length b.arity);
    b.arity <- a;
    let p = Array.make (12 * (i + 1)) 0 in
    Array.blit b.pos 0 p 0 (Array.length b.pos);
    b.pos <- p
  end;
  let floats k =
    if used + k > Float.Array.length b.nums then begin
      let a = Float.Array.create (2 * (used + k)) in
      Float.Array.blit b.nums 0 a 0 (Float.Array.length b.nums);
      b.nums <- a
    end
  in
  let used =
    match v with
    | Value.Float f ->
        floats 1;
        Float.Array.unsafe_set b.nums used f;
        Bytes.unsafe_set b.arity i '\000';
        used + 1
    | Value.Vector a when Array.length a >= 1 && Array.length a <= 254 ->
        let k = Array.length a in
        floats k;
        for j = 0 to k - 1 do
          Float.Array.unsafe_set b.nums (used + j) (Array.unsafe_get a j)
        done;
        Bytes.unsafe_set b.arity i (Char.unsafe_chr k);
        used + k
    | v ->
        b.others <- (i, v) :: b.others;
        Bytes.unsafe_set b.arity i '\255';
        used
  in
  (match b.files with
  | (_, f) :: _ when String.equal f s.pos_fname -> ()
  | _ -> b.files <- (i, s.pos_fname) :: b.files);
  let p = b.pos and o = 6 * i in
  p.(o) <- s.pos_lnum;
  p.(o + 1) <- s.pos_bol;
  p.(o + 2) <- s.pos_cnum;
  p.(o + 3) <- e.pos_lnum;
  p.(o + 4) <- e.pos_bol;
  p.(o + 5) <- e.pos_cnum;
  { store = b; count = i + 1; used }

let item_loc { store = b; _ } i =
  (* the file of the latest entry at or before [i] (later entries come
     first) *)
  let file = match List.find_opt (fun (j, _) -> j <= i) b.files with Some (_, f) -> f | None -> "" in
  let p k = b.pos.((6 * i) + k) in
  let at l bol c = { Lexing.pos_fname = file; pos_lnum = l; pos_bol = bol; pos_cnum = c } in
  Loc.make (at (p 0) (p 1) (p 2)) (at (p 3) (p 4) (p 5))

(* [f i v] on every item in order, [v] as the parser gave it *)
(* item [i] as the parser gave it, its floats at [off] of [b.nums] *)
let item_value b i off =
  match Char.code (Bytes.unsafe_get b.arity i) with
  | 0 -> Value.Float (Float.Array.get b.nums off)
  | 255 -> List.assoc i b.others
  | k -> Value.Vector (Array.init k (fun j -> Float.Array.get b.nums (off + j)))

(* how many floats item [i] holds in [b.nums] *)
let width b i = match Char.code (Bytes.unsafe_get b.arity i) with 0 -> 1 | 255 -> 0 | k -> k

let iter_items ({ store = b; count; _ } : items) f =
  let off = ref 0 in
  for i = 0 to count - 1 do
    f i (item_value b i !off);
    off := !off + width b i
  done

(* A vector of three read straight from the store (the common item: no
   value made for it), others through their value *)
let is_triple b i = Bytes.unsafe_get b.arity i = '\003'

let count loc what n k =
  let n = Value.to_int loc n in
  if n <> k then Diag.error loc "%s announces %d items but has %d" what n k

let vectors loc what n b =
  count loc what n b.count;
  let { store; count = k; _ } = b in
  let a = Float.Array.create (3 * k) in
  let off = ref 0 in
  for i = 0 to k - 1 do
    let o = !off in
    if is_triple store i then Float.Array.blit store.nums o a (3 * i) 3
    else begin
      let v = item_value store i o in
      (* the location only where to_vec3 needs it, for its message *)
      let loc = match v with Value.Float _ | Value.Vector _ -> Loc.none | _ -> item_loc b i in
      let p = Value.to_vec3 loc v in
      Float.Array.set a (3 * i) p.x;
      Float.Array.set a ((3 * i) + 1) p.y;
      Float.Array.set a ((3 * i) + 2) p.z
    end;
    off := o + width store i
  done;
  a

let vertex_vectors loc n items = Verts (vectors loc "vertex_vectors" n items)
let normal_vectors loc n items = Normals (vectors loc "normal_vectors" n items)

(* [x], an index of item [i], a face, as an integer *)
let face_index b i x =
  if Float.of_int (int_of_float x) <> x then Diag.error (item_loc b i) "face index %g is not an integer" x;
  int_of_float x

(* the three indices of item [i], a face, written at [at] *)
let index_triple b i v into at =
  match v with
  | Value.Vector a when Array.length a >= 3 ->
      for j = 0 to 2 do
        into.(at + j) <- face_index b i a.(j)
      done
  | v -> Diag.error (item_loc b i) "expected a vector of three indices <a, b, c>, found %s" (Value.type_name v)

(* face_indices items: a vector, optionally followed by 1 or 3 texture indices *)
let face_indices loc n b =
  let { store; count = k; _ } = b in
  let f = Array.make (3 * k) 0 and t = Array.make k (-1) and nf = ref 0 in
  let off = ref 0 in
  for i = 0 to k - 1 do
    let o = !off in
    (if is_triple store i then begin
       for j = 0 to 2 do
         f.((3 * !nf) + j) <- face_index b i (Float.Array.get store.nums (o + j))
       done;
       t.(!nf) <- -1;
       incr nf
     end
     else
       match item_value store i o with
       | Value.Float x ->
           (* the first texture index after a face is its texture; the
              second and third (per vertex) are ignored *)
           if !nf > 0 && t.(!nf - 1) = -1 then t.(!nf - 1) <- int_of_float x
       | v ->
           index_triple b i v f (3 * !nf);
           t.(!nf) <- -1;
           incr nf);
    off := o + width store i
  done;
  count loc "face_indices" n !nf;
  let t = Array.sub t 0 !nf in
  Faces (loc, Array.sub f 0 (3 * !nf), if Array.exists (fun x -> x >= 0) t then t else [||])

let normal_indices loc n b =
  count loc "normal_indices" n b.count;
  let f = Array.make (3 * b.count) 0 in
  iter_items b (fun i v -> index_triple b i v f (3 * i));
  Nfaces (loc, f)

let texture_list loc n ts =
  count loc "texture_list" n (List.length ts);
  Textures ts

let ignored_block = Ignored

let uv_vectors loc n b =
  count loc "uv_vectors" n b.count;
  let a = Float.Array.create (2 * b.count) in
  iter_items b (fun i v ->
      match v with
      | Value.Vector [| u; w |] -> Float.Array.set a (2 * i) u; Float.Array.set a ((2 * i) + 1) w
      | Value.Float u -> Float.Array.set a (2 * i) u; Float.Array.set a ((2 * i) + 1) u
      | v -> Diag.error (item_loc b i) "expected a uv vector <u, v>, found %s" (Value.type_name v));
  Uvs a

let uv_indices loc n b =
  count loc "uv_indices" n b.count;
  let f = Array.make (3 * b.count) 0 in
  iter_items b (fun i v -> index_triple b i v f (3 * i));
  Uv_faces (loc, f)

let mesh2 loc blocks =
  let verts = ref (Float.Array.create 0) and normals = ref (Float.Array.create 0) and faces = ref None
  and nfaces = ref None and texs = ref [] and uvs = ref None and uv_faces = ref None in
  List.iter (function
      | Verts v -> verts := v
      | Normals v -> normals := v
      | Faces (l, f, t) -> faces := Some (l, f, t)
      | Nfaces (l, f) -> nfaces := Some (l, f)
      | Textures t -> texs := t
      | Uvs a -> uvs := Some a
      | Uv_faces (l, f) -> uv_faces := Some (l, f)
      | Ignored -> ()) blocks;
  let nv = Float.Array.length !verts / 3 and nn = Float.Array.length !normals / 3 in
  let floc, faces, ftex =
    match !faces with Some x -> x | None -> Diag.error loc "a mesh2 needs face_indices"
  in
  Array.iter (fun i -> if i < 0 || i >= nv then Diag.error floc "vertex index %d out of range (0..%d)" i (nv - 1)) faces;
  let normal_faces =
    match !nfaces with
    | None -> if nn > 0 && nn = nv then Array.copy faces else [||]
    | Some (l, nf) ->
        if Array.length nf <> Array.length faces then
          Diag.error l "normal_indices must have one entry per face (%d), found %d" (Array.length faces / 3)
            (Array.length nf / 3);
        Array.iter (fun i -> if i < 0 || i >= nn then Diag.error l "normal index %d out of range (0..%d)" i (nn - 1)) nf;
        nf
  in
  let nt = List.length !texs in
  Array.iter (fun i -> if i >= nt then Diag.error floc "texture index %d out of range (texture_list has %d)" i nt) ftex;
  let normals = !normals in
  let normal_faces =
    Array.mapi (fun i k -> let b = 3 * (i / 3) in
      let z j = let q = normal_faces.(b + j) in
        Float.Array.get normals (3 * q) = 0. && Float.Array.get normals ((3 * q) + 1) = 0.
        && Float.Array.get normals ((3 * q) + 2) = 0. in
      if z 0 || z 1 || z 2 then -1 else k) normal_faces
  in
  (* uv_vectors without uv_indices: the face indices pick them (POV-Ray) *)
  let uvs, uv_faces =
    match (!uvs, !uv_faces) with
    | None, None -> (Float.Array.create 0, [||])
    | None, Some (l, _) -> Diag.error l "uv_indices without uv_vectors"
    | Some a, f ->
        let nu = Float.Array.length a / 2 in
        let l, f = match f with Some (l, f) -> (l, f) | None -> (floc, Array.copy faces) in
        if Array.length f <> Array.length faces then
          Diag.error l "uv_indices must have one entry per face (%d), found %d" (Array.length faces / 3)
            (Array.length f / 3);
        Array.iter (fun i -> if i < 0 || i >= nu then Diag.error l "uv index %d out of range (0..%d)" i (nu - 1)) f;
        (a, f)
  in
  Sdl.Mesh
    { verts = !verts; normals; faces; normal_faces; face_textures = ftex;
      textures = Array.of_list !texs; inside_vector = None; uvs; uv_faces }

let inside_vector loc v (o : Sdl.obj) =
  match o.shape with
  | Sdl.Mesh m -> { o with shape = Sdl.Mesh { m with inside_vector = Some v } }
  | _ -> Diag.warning loc "'inside_vector' only applies to meshes; ignored"; o

let csg l op items =
  let children = List.filter_map (function `Child o -> Some o | `Mod _ -> None) items in
  let mods = List.filter_map (function `Mod m -> Some m | `Child _ -> None) items in
  obj l (Sdl.Csg (op, children)) mods

let light_group l children mods =
  let global = List.fold_left (fun g m -> match m with `Global b -> b | `Xf _ -> g) false mods in
  let xfs = List.filter_map (function `Xf t -> Some (Sdl.transform_obj t) | `Global _ -> None) mods in
  obj l (Sdl.Light_group (global, children)) xfs

let default_texture (o : Sdl.obj) =
  match (o.texture, o.shape) with
  | None, Sdl.Light _ | Some _, _ -> o
  | None, _ -> if Defaults.texture_set () then { o with texture = Some [ Defaults.texture () ] } else o
