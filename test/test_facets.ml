(* The facets normal: POV-Ray's formula (normal.cpp) checked against a
   search of its own over crackle's feature points (Pattern.feature_point)
   and POV-Ray's DNoise, through the scene language; its properties; its
   errors. *)
open Camlray

(* The facets normal a camera's normal { } makes, at a world point with
   a world normal. *)
let normal_of text =
  match (Scn.compile ("camera { normal { " ^ text ^ " } }")).camera.normal with
  | Some nm -> nm
  | None -> Alcotest.failf "no normal in %S" text

let perturb nm (px, py, pz) (nx, ny, nz) =
  let p = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
  Vec3.set p px py pz;
  Vec3.set n nx ny nz;
  Normal.perturb_m nm p n out;
  (out.mx, out.my, out.mz)

let point cx cy cz =
  let v = Vec3.m () in
  Pattern.feature_point (float_of_int cx) (float_of_int cy) (float_of_int cz) v;
  (v.mx, v.my, v.mz)

(* the feature point nearest (tx, ty, tz) among the cubes [cubes] around
   its own, by [dist] (the first of equals, in the order given) *)
let nearest cubes dist (tx, ty, tz) =
  let fx = int_of_float (Float.floor tx) and fy = int_of_float (Float.floor ty)
  and fz = int_of_float (Float.floor tz) in
  let best = ref None in
  List.iter
    (fun (i, j, k) ->
      let ((x, y, z) as p) = point (fx + i) (fy + j) (fz + k) in
      let d = dist (x -. tx) (y -. ty) (z -. tz) in
      match !best with Some (bd, _) when bd <= d -> () | _ -> best := Some (d, p))
    cubes;
  snd (Option.get !best)

let block r =
  List.concat_map
    (fun i -> List.concat_map (fun j -> List.init ((2 * r) + 1) (fun k -> (i, j, k - r))) (List.init ((2 * r) + 1) (fun j -> j - r)))
    (List.init ((2 * r) + 1) (fun i -> i - r))

(* POV-Ray's 81: the 5x5x5 block less the cubes two away along two or
   three axes, x outermost *)
let knight = List.filter (fun (i, j, k) -> List.length (List.filter (fun v -> abs v = 2) [ i; j; k ]) <= 1) (block 2)
let euclid dx dy dz = (dx *. dx) +. (dy *. dy) +. (dz *. dz)

let unit (x, y, z) =
  let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  (x /. l, y /. l, z /. l)

let check msg (ex, ey, ez) (x, y, z) = Scn.check_floats ~eps:1e-12 msg [ ex; ey; ez ] [ x; y; z ]

(* deterministic pseudo-random unit normals and points *)
let normals =
  let s = Random.State.make [| 7 |] in
  List.init 400 (fun _ ->
      let g () = Random.State.float s 2. -. 1. in
      unit (g (), g (), g ()))

let points =
  let s = Random.State.make [| 11 |] in
  List.init 400 (fun _ ->
      let g () = Random.State.float s 20. -. 10. in
      (g (), g (), g ()))

(* without coords: the normal is the nearest feature point to n / size,
   normalised; the nearest in a 7x7x7 block (every point near enough is
   in POV-Ray's 81 cubes) *)
let snapped () =
  Alcotest.(check int) "81 cubes" 81 (List.length knight);
  let all = block 3 in
  List.iter
    (fun (text, size) ->
      let nm = normal_of text in
      List.iteri
        (fun i ((nx, ny, nz) as n) ->
          let t = (nx /. size, ny /. size, nz /. size) in
          let p = (float_of_int i, 0.5, -3.) in
          check (Printf.sprintf "%s, normal %d" text i) (unit (nearest all euclid t)) (perturb nm p n))
        normals)
    [ ("facets", 0.1); ("facets size 0.3", 0.3); ("facets size 2", 2.); ("facets 0.9 size 0.05", 0.05) ]

(* other metrics: the least sum among POV-Ray's 81 cubes; metric 1 sums
   the differences with their signs, as POV-Ray does *)
let metrics () =
  let sum dx dy dz = dx +. dy +. dz in
  let cube dx dy dz = (Float.abs dx ** 3.) +. (Float.abs dy ** 3.) +. (Float.abs dz ** 3.) in
  List.iter
    (fun (text, dist) ->
      let nm = normal_of text in
      List.iteri
        (fun i ((nx, ny, nz) as n) ->
          let t = (nx /. 0.2, ny /. 0.2, nz /. 0.2) in
          check (Printf.sprintf "%s, normal %d" text i) (unit (nearest knight dist t)) (perturb nm (0., 0., 0.) n))
        normals)
    [ ("facets size 0.2 metric 1", sum); ("facets size 0.2 metric 3", cube) ]

(* with coords: the normal tilted by coords times the part of POV-Ray's
   DNoise at the nearest feature point (to the point / size) perpendicular to
   it *)
let tilted () =
  List.iter
    (fun (text, coords, size) ->
      let nm = normal_of text in
      List.iteri
        (fun i ((px, py, pz) as p) ->
          let ((nx, ny, nz) as n) = List.nth normals i in
          let fx, fy, fz = nearest (block 3) euclid (px /. size, py /. size, pz /. size) in
          let d = Vec3.m () in
          Noise.dnoise fx fy fz d;
          let k = (d.mx *. nx) +. (d.my *. ny) +. (d.mz *. nz) in
          let e =
            unit
              ( nx +. (coords *. (d.mx -. (k *. nx))),
                ny +. (coords *. (d.my -. (k *. ny))),
                nz +. (coords *. (d.mz -. (k *. nz))) )
          in
          check (Printf.sprintf "%s, point %d" text i) e (perturb nm p n))
        points)
    [ ("facets coords 0.5", 0.5, 0.1); ("facets coords 1.5 size 0.7", 1.5, 0.7) ]

(* flat facets: within one cell of the feature points (points sharing
   their nearest) a flat surface gets one normal; the noise's tilt is
   perpendicular, so it never flips the normal; a uniform scale scales the
   facets *)
let properties () =
  let nm = normal_of "facets coords 0.8 size 0.5" in
  let scaled = normal_of "facets coords 0.8 size 0.5 scale 3" in
  let up = (0., 1., 0.) in
  let cell (x, z) = nearest (block 3) euclid (x /. 0.5, 0., z /. 0.5) in
  let s = Random.State.make [| 3 |] in
  let same = ref 0 in
  for _ = 1 to 2000 do
    let a = (Random.State.float s 6., Random.State.float s 6.) in
    let b = (fst a +. Random.State.float s 0.2, snd a +. Random.State.float s 0.2) in
    let at (x, z) = perturb nm (x, 0., z) up in
    let _, ny, _ = at a in
    if ny <= 0. then Alcotest.fail "a facet faces away";
    if cell a = cell b then begin
      incr same;
      check "one normal per cell" (at a) (at b)
    end
    else if at a = at b then Alcotest.fail "two cells, one normal";
    let x, z = a in
    check "scale 3: the facets three times as large" (at a) (perturb scaled (3. *. x, 0., 3. *. z) up)
  done;
  if !same < 1000 then Alcotest.failf "only %d pairs in one cell" !same;
  (* facets without coords leave a flat surface flat: one normal along y *)
  let flat = normal_of "facets" in
  let a = perturb flat (0.3, 0., 0.2) up and b = perturb flat (7.1, 0., -4.) up in
  check "size form: a plane keeps one normal" a b

(* the hot path allocates nothing (the cache refilled as the cube changes) *)
let no_allocation () =
  let nm = normal_of "facets coords 0.5" and snap = normal_of "facets metric 3" in
  let p = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
  Normal.perturb_m nm p n out;
  let before = Gc.minor_words () in
  for i = 1 to 1000 do
    Vec3.set p (0.37 *. float_of_int i) 0.1 (-0.2 *. float_of_int i);
    Vec3.set n (Float.sin (float_of_int i)) 1. (Float.cos (float_of_int i));
    Vec3.normalize_m n;
    Normal.perturb_m nm p n out;
    Normal.perturb_m snap p n out
  done;
  let words = Gc.minor_words () -. before in
  if words > 0. then Alcotest.failf "%.0f minor words for 2000 facets normals" words

let errors () =
  Scn.check_message "sphere { 0, 1 pigment { facets } }" "facets can only be used in a normal";
  Scn.check_message "sphere { 0, 1 texture { facets } }" "facets can only be used in a normal";
  Scn.check_message "sphere { 0, 1 normal { bumps coords 0.5 } }" "coords can only be used with facets";
  Scn.check_message "sphere { 0, 1 normal { bumps size 0.5 } }" "size can only be used with facets";
  Scn.check_message "sphere { 0, 1 normal { facets metric 0 } }" "metric must be positive";
  Scn.check_message "sphere { 0, 1 normal { facets normal_map { [0 bumps] [1 dents] } } }" "facets takes no normal_map";
  (* a declared facets normal keeps its form and takes more *)
  let nm = normal_of "facets coords 0.4" in
  let again =
    match
      (Scn.compile "#declare F = normal { facets size 0.2 }\ncamera { normal { F coords 0.4 size 0.1 } }")
        .camera
        .normal
    with
    | Some n -> n
    | None -> Alcotest.fail "no normal"
  in
  List.iteri
    (fun i p -> check "declared, then coords" (perturb nm p (List.nth normals i)) (perturb again p (List.nth normals i)))
    points

let tests =
  ( "facets",
    [
      Alcotest.test_case "size form: the nearest feature point, normalised" `Quick snapped;
      Alcotest.test_case "metrics 1 and 3 over POV-Ray's 81 cubes" `Quick metrics;
      Alcotest.test_case "coords form: the noise's perpendicular part" `Quick tilted;
      Alcotest.test_case "one normal a cell, facing out, scaled" `Quick properties;
      Alcotest.test_case "allocation-free" `Quick no_allocation;
      Alcotest.test_case "errors and declared facets" `Quick errors;
    ] )
