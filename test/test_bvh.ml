(* BVH: the scene's nearest hit and its list of shadow crossings equal a
   brute-force walk over every object, on random scenes. *)
open Camlray
open Geom_gen

let scene objects =
  Scene.make ~objects ~lights:[||] ~camera:Camera.default ~background:Color.black
    ~settings:Scene.default_settings ()

(* random objects spread over a 20-unit cube, some CSG, some infinite *)
let gobj =
  let open QCheck.Gen in
  let place = map2 (fun xf t -> Transform.then_ xf (Transform.translate t)) gxform (gvec 10.) in
  let leaf = map2 (fun s xf -> Object.make ~xform:xf s) gshape place in
  oneof_weighted
    [
      (20, leaf);
      (* plain spheres: the scene tests these from a flat array *)
      (10, map3 (fun c r ns -> Object.make ~no_shadow:ns (Shape.sphere c r)) (gvec 10.) (fr 0.2 2.)
             (map (fun k -> k = 0) (int_bound 5)));
      (2, map2 (fun a b -> Object.intersection [| a; b |]) leaf leaf);
      (2, map2 (fun xf s -> let a = Object.make ~xform:xf (Shape.sphere Vec3.zero 1.5) in
                 Object.intersection [| a; Object.invert (Object.make ~xform:xf s) |]) place gshape);
      (1, map2 (fun n d -> Object.make (Shape.plane n d)) gdir (fr (-15.) 15.));
      (* a union large enough to get its own BVH, alone and inside CSG *)
      (1, map (fun l -> Object.union (Array.of_list l)) (list_size (return 10) leaf));
      (1, map2 (fun a l -> Object.intersection [| a; Object.invert (Object.union (Array.of_list l)) |])
            leaf (list_size (return 12) leaf));
    ]

let gscene = QCheck.Gen.(pair (list_size (int_range 0 60) gobj) (list_size (return 30) (map2 (fun o d -> Ray.make o d) (gvec 15.) gdir)))

let brute objects r =
  let best = ref infinity and leaf = ref None in
  Array.iter (fun o ->
      let h = Hit.create !best and f = Object.found o in
      if Object.hit o r 1e-9 h f then (best := h.t; leaf := Some f.leaf)) objects;
  (!best, !leaf)

let rec leaves (o : Object.t) =
  match o.geom with
  | Object.Prim _ -> [ o ]
  | Object.Union cs | Object.Intersection cs | Object.Merge cs -> List.concat_map leaves (Array.to_list cs)

let arb = QCheck.make ~print:(fun (l, _) -> Printf.sprintf "%d objects" (List.length l)) gscene

let props =
  [
    QCheck.Test.make ~name:"BVH nearest hit = brute force" ~count:200 arb (fun (objs, rays) ->
        let s = scene (Array.of_list objs) in
        let objects = s.objects in
        List.for_all (fun r ->
            let t, leaf = brute objects r in
            match Scene.intersect s r 1e-9 infinity, leaf with
            | None, None -> true
            | Some h, Some l ->
                let n = Object.normal l h.point (Hit.create 0.) in
                h.t = t && (h.obj == l || h.t = t)
                (* the leaf hit is one of the scene's own *)
                && List.memq h.obj (List.concat_map leaves (Array.to_list objects))
                && (match l.geom with Object.Prim (Shape.Sphere _) when h.obj == l -> Vec3.dist n h.normal < 1e-12 | _ -> true)
            | Some h, None -> QCheck.Test.fail_reportf "BVH found t=%g, brute force nothing" h.t
            | None, Some _ -> QCheck.Test.fail_reportf "BVH missed the hit at t=%g" t) rays);
    QCheck.Test.make ~name:"occluders: same crossings as brute force" ~count:200 arb (fun (objs, rays) ->
        let objects = Array.of_list objs in
        let s = scene objects in
        List.for_all (fun r ->
            let a = ref [] and b = ref [] in
            ignore (Scene.occluders s r 1e-9 30. Object.never (fun _ t -> a := t :: !a; true));
            Array.iter (fun o -> ignore (Object.crossings o r 1e-9 30. (fun (l : Object.t) t -> if not l.no_shadow then b := t :: !b; true))) objects;
            List.sort compare !a = List.sort compare !b) rays);
    QCheck.Test.make ~name:"containing = every object's inside test, last first" ~count:300
      (QCheck.make ~print:(fun (l, _) -> Printf.sprintf "%d objects" (List.length l))
         QCheck.Gen.(pair (list_size (int_range 0 60) gobj) (list_size (return 40) (gvec 12.))))
      (fun (objs, points) ->
        let s = scene (Array.of_list objs) in
        List.for_all (fun p ->
            let brute = Array.fold_left (fun acc o -> if Object.inside o p then o :: acc else acc) [] s.objects in
            let got = Scene.containing s p in
            List.length got = List.length brute && List.for_all2 ( == ) got brute) points);
    QCheck.Test.make ~name:"occluders stops when told to" ~count:100 arb (fun (objs, rays) ->
        let s = scene (Array.of_list objs) in
        List.for_all (fun r ->
            let n = ref 0 in
            let all = Scene.occluders s r 1e-9 30. Object.never (fun _ _ -> incr n; false) in
            (all && !n = 0) || ((not all) && !n = 1)) rays);
  ]

(* A triangle soup of 1 to 60 triangles in a 3-unit cube, placed. *)
let gmesh_obj =
  let open QCheck.Gen in
  map3
    (fun n seed xf ->
      let st = Random.State.make [| n; seed |] in
      let c () = Random.State.float st 3. -. 1.5 in
      let verts = Float.Array.init (9 * n) (fun _ -> c ()) in
      let m =
        Mesh.make ~par:None ~verts ~normals:(Float.Array.create 0) ~faces:(Array.init (3 * n) Fun.id)
          ~normal_faces:[||] ~inside_vector:None ()
      in
      Object.make ~xform:xf (Shape.Mesh m))
    (int_range 1 60) int gxform

let is_mesh (o : Object.t) = match o.geom with Object.Prim (Shape.Mesh _) -> true | _ -> false

(* Shadow rays through opaque meshes ask for any crossing, not all: the
   same rays are blocked, and a mesh's any-hit finds a crossing exactly
   when its nearest hit does. *)
let any_hit_props =
  let arb =
    QCheck.make ~print:(fun (l, _) -> Printf.sprintf "%d objects" (List.length l))
      QCheck.Gen.(pair (list_size (int_range 1 20) (oneof_weighted [ (2, gmesh_obj); (1, gobj) ]))
                    (list_size (return 30) gray))
  in
  [
    QCheck.Test.make ~name:"opaque meshes: a shadow ray is blocked as when all crossings are walked"
      ~count:200 arb (fun (objs, rays) ->
        let s = scene (Array.of_list objs) in
        List.for_all (fun r ->
            let walked = Scene.occluders s r 1e-9 30. Object.never (fun _ _ -> false) in
            let calls = ref 0 in
            let sr = Ray.of_ray r in
            sr.far <- 30.;
            let any =
              Scene.occluders_s s sr 1e-9 is_mesh (fun o (h : Hit.t) ->
                  let t = h.t in
                  incr calls;
                  if is_mesh o then QCheck.Test.fail_report "called on an opaque mesh";
                  if not (t > 1e-9 && t < 30.) then QCheck.Test.fail_reportf "crossing at t=%g" t;
                  false)
            in
            walked = any && !calls <= 1) rays);
    QCheck.Test.make ~name:"opaque objects: blocked as when walked, never passed to the callback"
      ~count:200 arb (fun (objs, rays) ->
        let s = scene (Array.of_list objs) in
        List.for_all (fun r ->
            let walked = Scene.occluders s r 1e-9 30. Object.never (fun _ _ -> false) in
            let sr = Ray.of_ray r in
            sr.far <- 30.;
            let any = Scene.occluders_s s sr 1e-9 (fun _ -> true) (fun _ _ -> QCheck.Test.fail_report "called") in
            walked = any) rays);
    QCheck.Test.make ~name:"Mesh.any_s finds a crossing exactly when Mesh.hit_s does" ~count:300
      (QCheck.make QCheck.Gen.(pair gmesh_obj (list_size (return 30) gray)))
      (fun (o, rays) ->
        match o.geom with
        | Object.Prim (Shape.Mesh m) ->
            List.for_all (fun r ->
                let sr = Ray.of_ray r in
                let h = Hit.create 20. and h' = Hit.create 20. in
                let near = Mesh.hit_s m sr 1e-9 h and any = Mesh.any_s m sr 1e-9 h' in
                near = any && ((not any) || (h'.t >= h.t && h'.t < 20.))) rays
        | _ -> false);
  ]

let union_prop =
  QCheck.Test.make ~name:"a union's own BVH finds the nearest child hit" ~count:200
    (QCheck.make QCheck.Gen.(pair (list_size (int_range 8 40) gobj) (list_size (return 20) gray)))
    (fun (l, rays) ->
      let cs = Array.of_list l in
      let u = Object.union cs in
      u.index <> None
      && List.for_all (fun r ->
             let t, _ = brute cs r in
             Object.intersect u r 1e-9 infinity = t) rays)

let boxes l = Float.Array.of_list (List.concat_map (fun (a, b) -> [ a; a; a; b; b; b ]) l)

let units =
  [
    Alcotest.test_case "Scratch: one value per domain, kept" `Quick (fun () ->
        let made = Atomic.make 0 in
        let k = Scratch.key (fun () -> Atomic.incr made; ref 0) in
        let v0 = Scratch.get k in
        v0 := 7;
        Alcotest.(check bool) "same value again" true (Scratch.get k == v0);
        Alcotest.(check int) "kept" 7 !(Scratch.get k);
        (* the main domain is alive meanwhile: the other one has its own *)
        let v1 = Domain.join (Domain.spawn (fun () -> Scratch.get k)) in
        Alcotest.(check bool) "another domain, another value" true (v1 != v0);
        Alcotest.(check int) "made once per domain" 2 (Atomic.get made));
    Alcotest.test_case "empty BVH" `Quick (fun () ->
        let b = Bvh.build (Float.Array.create 0) in
        Alcotest.(check int) "no nodes" 0 (Bvh.nodes b);
        let h = Hit.create infinity in
        Bvh.nearest b (Ray.make Vec3.zero Vec3.unit_z) 0. h (fun _ -> Alcotest.fail "called");
        Alcotest.(check bool) "iter" true (Bvh.iter b (Ray.make Vec3.zero Vec3.unit_z) 0. 1. (fun _ -> false)));
    Alcotest.test_case "identical boxes split anyway" `Quick (fun () ->
        let b = Bvh.build (boxes (List.init 1000 (fun _ -> (0., 1.)))) in
        Alcotest.(check int) "size" 1000 (Bvh.size b);
        let seen = ref 0 in
        ignore (Bvh.iter b (Ray.make (Vec3.make 0.5 0.5 (-1.)) Vec3.unit_z) 0. 10. (fun _ -> incr seen; true));
        Alcotest.(check int) "all visited" 1000 !seen);
    Alcotest.test_case "the SAH weighs primitive and node costs" `Quick (fun () ->
        (* 16 unit boxes in a row along x, 0.5 apart *)
        let bs = boxes (List.init 16 (fun i -> (1.5 *. float i, (1.5 *. float i) +. 1.))) in
        let seen b x =
          let n = ref 0 in
          ignore (Bvh.iter b (Ray.make (Vec3.make x x (-5.)) Vec3.unit_z) 0. 100. (fun _ -> incr n; true));
          !n
        in
        (* a walk as dear as 1 test: split down to leaves of one or two *)
        let b1 = Bvh.build ~leaf_size:16 bs in
        Alcotest.(check bool) "node cost 1: several nodes" true (Bvh.nodes b1 > 8);
        Alcotest.(check bool) "node cost 1: a ray meets one or two boxes' leaves" true (seen b1 0.5 <= 2);
        (* a walk as dear as 64 tests: one leaf of all 16 *)
        let b64 = Bvh.build ~leaf_size:16 ~node_cost:64. bs in
        Alcotest.(check int) "node cost 64: one node" 1 (Bvh.nodes b64);
        Alcotest.(check int) "node cost 64: every primitive tested" 16 (seen b64 0.5);
        (* the same with box 0 a hundred times dearer: it keeps a leaf of its own *)
        let cost = Float.Array.init 16 (fun i -> if i = 0 then 100. else 1.) in
        let b = Bvh.build ~leaf_size:16 ~node_cost:64. ~cost bs in
        Alcotest.(check int) "the dear primitive alone" 1 (seen b 0.5);
        Alcotest.(check bool) "the cheap ones still packed" true (seen b 12.5 >= 8));
    Alcotest.test_case "a parallel build gives the same tree, node for node" `Quick (fun () ->
        (* random boxes, some of them identical (the midpoint fallback),
           costs that vary; tasks run in reverse order, then on 2 and 3
           domains *)
        let st = Random.State.make [| 17 |] in
        List.iter
          (fun n ->
            let bs = Float.Array.create (6 * n) in
            for i = 0 to n - 1 do
              let same = i mod 7 = 0 in
              for a = 0 to 2 do
                let lo = if same then 0.5 else Random.State.float st 100. in
                Float.Array.set bs ((6 * i) + a) lo;
                Float.Array.set bs ((6 * i) + 3 + a) (lo +. Random.State.float st 2.)
              done
            done;
            let cost = Float.Array.init n (fun i -> 1. +. float (i mod 3)) in
            let serial = Bvh.build ~leaf_size:8 ~node_cost:2. ~cost bs in
            let reverse n f = for i = n - 1 downto 0 do f i done in
            let check name par =
              let b = Bvh.build ~leaf_size:8 ~node_cost:2. ~cost ~par bs in
              Alcotest.(check int) (name ^ ": nodes") (Bvh.nodes serial) (Bvh.nodes b);
              if b <> serial then Alcotest.failf "%d boxes, %s: a different tree" n name
            in
            check "reverse order" reverse;
            check "2 domains" (Render.parallel ~domains:2);
            check "3 domains" (Render.parallel ~domains:3))
          [ 100; 1 lsl 14; 40_000; 100_000 ]);
    Alcotest.test_case "boxes the ray misses are not visited" `Quick (fun () ->
        let b = Bvh.build (boxes (List.init 100 (fun i -> (float i, float i +. 0.5)))) in
        let seen = ref [] in
        ignore (Bvh.iter b (Ray.make (Vec3.make 10.2 10.2 (-1.)) Vec3.unit_z) 0. 100. (fun i -> seen := i :: !seen; true));
        Alcotest.(check (list int)) "only box 10" [ 10 ] !seen);
  ]

let opaque_all (_ : Object.t) = true
let no_light (_ : Object.t) (_ : Hit.t) = false

(* The traversal and intersection kernel allocates nothing: every leaf
   kind, transforms, a union with its own BVH, a mesh, CSG and a clip
   (whose rejected crossings alone may box a float). *)
let no_alloc =
  Alcotest.test_case "Scene.nearest, the shadow walk and containing_into allocate nothing" `Quick (fun () ->
      let s =
        Helpers.compile_string
          {|camera { location <0, 3, -12> look_at <0, 0, 0> }
plane { y, -1 pigment { rgb 1 } }
#for (I, 0, 11)
  sphere { <I - 6, 0, 0>, 0.4 pigment { rgb 1 } }
  sphere { 0, 0.4 scale <1, 2, 1> translate <I - 6, 0, 2> pigment { rgb 1 } }
#end
box { -0.5, 0.5 rotate <10, 20, 30> translate <-3, 0, -2> pigment { rgb 1 } }
cone { 0, 0.5, y, 0.1 scale <1, 1.5, 1> translate <-1, 0, -2> pigment { rgb 1 } }
torus { 0.6, 0.2 rotate x*40 translate <1, 0, -2> pigment { rgb 1 } }
disc { <3, 0, -2>, <0, 0, -1>, 0.5 pigment { rgb 1 } }
triangle { <4, 0, -2>, <5, 0, -2>, <4.5, 1, -2> pigment { rgb 1 } }
mesh { triangle { <-5, 1, -3>, <-4, 1, -3>, <-4.5, 2, -3> } triangle { <-4, 1, -3>, <-3, 1, -3>, <-3.5, 2, -3> } pigment { rgb 1 } }
union { #for (I, 0, 9) sphere { <I - 5, 2, 3>, 0.3 scale <1, 1.2, 1> } #end pigment { rgb 1 } }
|}
      in
      let rays = Camlray_bench.Bench.camera_rays s ~width:80 ~height:50 in
      let pass = Camlray_bench.Bench.nearest_pass s rays in
      ignore (pass ());
      let before = Gc.minor_words () in
      let hits = pass () in
      let words = Gc.minor_words () -. before in
      Alcotest.(check bool) "some rays hit" true (hits > 1000);
      (* a few words of slack, nothing per ray *)
      if words > 16. then Alcotest.failf "%.0f minor words for %d rays" words (Array.length rays);
      (* the shadow walk over the same rays, every object opaque, its range
         (30 units) read from the ray *)
      let r = Ray.scratch () in
      let blocked = ref 0 in
      let walk () =
        Array.iter (fun ray ->
            Ray.load r ray;
            r.far <- 30.;
            if not (Scene.occluders_s s r 1e-3 opaque_all no_light) then incr blocked) rays
      in
      walk ();
      blocked := 0;
      let before = Gc.minor_words () in
      walk ();
      let words = Gc.minor_words () -. before in
      Alcotest.(check bool) "some rays blocked" true (!blocked > 1000);
      if words > 16. then Alcotest.failf "%.0f minor words for %d shadow walks" words (Array.length rays);
      (* where camera rays start (focal blur moves the origin at every
         ray): points among the objects, outside all of them and in front
         of the disc (whose inside is the half-space behind it) *)
      let p = Vec3.m () and none = ref true and held = Scene.objects () in
      let probe () =
        for i = 0 to 999 do
          Vec3.set p (float (i mod 12) -. 6.) 1.5 (-2.8 -. (float (i mod 7) *. 0.001));
          Scene.containing_into s p held;
          if held.n > 0 then none := false
        done
      in
      probe ();
      let before = Gc.minor_words () in
      probe ();
      let words = Gc.minor_words () -. before in
      Alcotest.(check bool) "inside nothing" true !none;
      if words > 16. then Alcotest.failf "%.0f minor words for 1000 points" words)

let tests = ("bvh", no_alloc :: units @ List.map QCheck_alcotest.to_alcotest ((union_prop :: props) @ any_hit_props))
