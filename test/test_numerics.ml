(* No NaN or infinite value ever reaches an image: random valid scenes
   (random shapes, transforms including near-degenerate scales, lights,
   materials), rendered in both modes. *)
open Camlray

let gen_scene =
  let open QCheck.Gen in
  let f lo hi = map (Printf.sprintf "%.6g") (float_range lo hi) in
  let vec lo hi = map3 (Printf.sprintf "<%s,%s,%s>") (f lo hi) (f lo hi) (f lo hi) in
  let scale =
    oneof
      [ f 0.1 3.; return "1e-7"; return "<1e-9, 1, 1>"; return "<-1, 1, 1>"; vec (-3.) 3. ]
  in
  let transform =
    oneof
      [ map (Printf.sprintf "scale %s") scale; map (Printf.sprintf "rotate %s") (vec (-180.) 180.);
        map (Printf.sprintf "translate %s") (vec (-3.) 3.) ]
  in
  let finish =
    map3
      (fun (a, d) (r, p) (s, rough) ->
        Printf.sprintf "finish { ambient %s diffuse %s reflection %s phong %s specular %s roughness %s }"
          a d r p s rough)
      (pair (f 0. 1.) (f 0. 1.)) (pair (f 0. 1.) (f 0. 1.)) (pair (f 0. 1.) (f 0.0001 1.))
  in
  let pigment = map2 (Printf.sprintf "pigment { rgbft <%s, %s, 0.5, 0.3, 0.3> }") (f 0. 1.) (f 0. 1.) in
  let interior = map (Printf.sprintf "interior { ior %s }") (f 0.5 2.5) in
  let obj =
    map3
      (fun shape mods (fin, pig, int) -> Printf.sprintf "%s %s %s %s %s }" shape pig fin int mods)
      (oneof
         [ map2 (Printf.sprintf "sphere { %s, %s") (vec (-3.) 3.) (f 1e-4 2.);
           map2 (Printf.sprintf "plane { %s, %s") (vec (-1.) 1.) (f (-2.) 2.) ])
      (map (String.concat " ") (list_size (int_range 0 3) transform))
      (triple finish pigment interior)
  in
  let light =
    map2 (Printf.sprintf "light_source { %s color rgb %s }") (vec (-5.) 5.) (f 0. 3.)
  in
  map2
    (fun objs lights ->
      String.concat "\n"
        ([ "#version 3.7;"; "camera { location <0,0,-6> look_at 0 }"; "background { rgb <0.2,0.3,0.4> }" ]
        @ objs @ lights))
    (list_size (int_range 1 6) obj) (list_size (int_range 0 3) light)

let finite_image img =
  let ok = ref true in
  for y = 0 to Image.height img - 1 do
    for x = 0 to Image.width img - 1 do
      List.iter
        (fun v -> if not (Float.is_finite v && v >= 0.) then ok := false)
        [ Image.get_r img x y; Image.get_g img x y; Image.get_b img x y ]
    done
  done;
  !ok

let prop =
  QCheck.Test.make ~name:"random scenes render finite, non-negative pixels in both modes" ~count:200
    (QCheck.make ~print:(fun s -> s) gen_scene)
    (fun text ->
      match Camlray_lang.Parse.string text with
      | Error d -> QCheck.Test.fail_reportf "generated scene rejected: %s" (Camlray_lang.Diag.to_string d)
      | Ok sdl -> (
          match Camlray_lang.Compile.scene sdl with
          | Error d -> QCheck.Test.fail_reportf "generated scene rejected: %s" (Camlray_lang.Diag.to_string d)
          | Ok s ->
              let w = 12 and h = 9 in
              finite_image (Render.image ~domains:1 ~width:w ~height:h (Whitted.pixel s ~width:w ~height:h))
              && finite_image
                   (Render.image ~domains:1 ~width:w ~height:h
                      (Path.pixel (Path.prepare s) ~width:w ~height:h ~seed:1 ~spp:2 ~max_depth:6))))

(* Floats.sort_prefix against List.sort: the first [n] in order, the
   rest untouched, nothing lost or made up (NaN-free lists, infinities
   and repeated values included) *)
let sort_prefix_prop =
  let open QCheck in
  let value = Gen.(oneof [ float_range (-1e3) 1e3; oneof_list [ 0.; -0.; 1.; infinity; neg_infinity ] ]) in
  Test.make ~name:"Floats.sort_prefix sorts the first n and leaves the rest" ~count:500
    (make
       ~print:Print.(pair (list float) int)
       Gen.(list_size (int_range 0 40) value >>= fun l -> map (fun n -> (l, n)) (int_range 0 (List.length l))))
    (fun (l, n) ->
      let a = Float.Array.of_list l in
      Floats.sort_prefix a n;
      let got = Float.Array.to_list a in
      let head = List.filteri (fun i _ -> i < n) l and tail = List.filteri (fun i _ -> i >= n) l in
      let sorted = List.sort Float.compare head in
      (* -0. and 0. compare equal: keep the count of each, not their order *)
      let same a b = List.length a = List.length b && List.for_all2 (fun x y -> x = y) a b in
      same (List.filteri (fun i _ -> i < n) got) sorted && List.filteri (fun i _ -> i >= n) got = tail)

let sort_prefix_bounds () =
  Alcotest.check_raises "n past the end" (Invalid_argument "Floats.sort_prefix") (fun () ->
      Floats.sort_prefix (Float.Array.make 3 0.) 4);
  let a = Float.Array.of_list [ 3.; 1.; 2. ] in
  Floats.sort_prefix a 0;
  Alcotest.(check (list (float 0.))) "n = 0 leaves the array" [ 3.; 1.; 2. ] (Float.Array.to_list a)

(* Floats.order_prefix against a stable List.sort of (value, index): the
   indices of the first [n] in order of value, ties in index order, the
   values untouched (the crossings of a shadow ray are ordered so) *)
let order_prefix_prop =
  let open QCheck in
  let value = Gen.(oneof [ float_range (-1e3) 1e3; oneof_list [ 0.; 1.; 2.; infinity ] ]) in
  Test.make ~name:"Floats.order_prefix orders the first n indices by value, stably" ~count:500
    (make
       ~print:Print.(pair (list float) int)
       Gen.(list_size (int_range 0 40) value >>= fun l -> map (fun n -> (l, n)) (int_range 0 (List.length l))))
    (fun (l, n) ->
      let a = Float.Array.of_list l in
      let ord = Array.make (List.length l + 3) (-1) in
      Floats.order_prefix a n ord;
      let expect =
        List.filteri (fun i _ -> i < n) l
        |> List.mapi (fun i x -> (x, i))
        |> List.stable_sort (fun (x, _) (y, _) -> Float.compare x y)
        |> List.map snd
      in
      Array.to_list (Array.sub ord 0 n) = expect && Float.Array.to_list a = l
      && Array.for_all (fun i -> i = -1) (Array.sub ord n (Array.length ord - n)))

let tests =
  ( "numerics",
    [ QCheck_alcotest.to_alcotest prop; QCheck_alcotest.to_alcotest sort_prefix_prop;
      QCheck_alcotest.to_alcotest order_prefix_prop;
      Alcotest.test_case "Floats.sort_prefix bounds" `Quick sort_prefix_bounds ] )
