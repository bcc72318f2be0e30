(* Whole renders: pixel values against computed colours, and images that
   do not depend on the domain count. *)
open Camlray

(* A plane z = 1 facing the default camera, lit by a light at the eye:
   colour = P (ambient 0.1 + diffuse 0.6 cos), cos = 1 / |p|. *)
let lit_plane =
  "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n\
   light_source { <0,0,0> color rgb 1 }\n\
   plane { -z, -1 pigment { rgb <1, 0.5, 0.25> } }\n"

let computed_8x8 () =
  let w = 8 and h = 8 in
  let img = Helpers.render_whitted ~width:w ~height:h lit_plane in
  for j = 0 to h - 1 do
    for i = 0 to w - 1 do
      let sx = ((float i +. 0.5) /. float w) -. 0.5 and sy = 0.5 -. ((float j +. 0.5) /. float h) in
      let p = Vec3.make (1.33 *. sx) sy 1. in
      let k = 0.1 +. (0.6 /. Vec3.length p) in
      let r, g, b = Helpers.pixel img i j in
      let check what e a =
        if Float.abs (e -. a) > 1e-9 then Alcotest.failf "pixel (%d,%d) %s: expected %g, got %g" i j what e a
      in
      check "r" k r;
      check "g" (0.5 *. k) g;
      check "b" (0.25 *. k) b
    done
  done

let same_images a b =
  let w = Image.width a and h = Image.height a in
  for y = 0 to h - 1 do
    for x = 0 to w - 1 do
      if Helpers.pixel a x y <> Helpers.pixel b x y then Alcotest.failf "pixel (%d,%d) differs" x y
    done
  done

let default_scene () =
  In_channel.with_open_bin (Filename.concat (Helpers.scenes_dir ()) "default.scn") In_channel.input_all

(* [loop ~domains n f] ran [f] on every index once, for each (domains, n) *)
let every_index_once (loop : domains:int -> Image.par) cases =
  List.iter
    (fun (domains, n) ->
      let seen = Array.init n (fun _ -> Atomic.make 0) in
      loop ~domains n (fun i -> Atomic.incr seen.(i));
      Array.iteri
        (fun i a ->
          if Atomic.get a <> 1 then
            Alcotest.failf "%d domains, %d indices: index %d ran %d times" domains n i (Atomic.get a))
        seen)
    cases

(* the domains other than the caller's that ran indices of [loop 64 f]
   (the caller's indices wait, up to 5 s, for another domain to take one) *)
let other_domains (loop : Image.par) =
  let ids = Array.make 64 (-1) and me = (Domain.self () :> int) and other = Atomic.make false in
  let t0 = Unix.gettimeofday () in
  loop 64 (fun i ->
      let d = (Domain.self () :> int) in
      ids.(i) <- d;
      if d <> me then Atomic.set other true
      else while not (Atomic.get other) && Unix.gettimeofday () -. t0 < 5. do Domain.cpu_relax () done);
  List.sort_uniq compare (List.filter (fun d -> d <> me) (Array.to_list ids))

let units =
  [
    Alcotest.test_case "8x8 whitted image equals the computed colours" `Quick computed_8x8;
    Alcotest.test_case "the parallel loop runs every index once, whatever the chunks" `Quick (fun () ->
        (* tasks take up to 4 indices, at least 96 tasks a domain: sizes
           around each chunk boundary *)
        every_index_once Render.parallel
          [ (1, 0); (2, 0); (2, 1); (2, 63); (2, 64); (2, 127); (2, 128); (2, 257); (2, 383); (2, 384);
            (2, 767); (2, 768); (3, 383); (3, 385); (3, 575); (3, 577); (4, 1535); (4, 1537);
            (2, 7500); (4, 1875); (4, 1999) ]);
    Alcotest.test_case "pulled runs every index once, on every domain" `Quick (fun () ->
        every_index_once Render.pulled [ (1, 0); (1, 5); (2, 0); (2, 1); (2, 2); (2, 3); (3, 2); (2, 128); (4, 1000) ];
        (* while the caller's first index waits, another domain takes
           indices: the counter is shared, not split in advance *)
        Alcotest.(check int) "another domain took indices" 1 (List.length (other_domains (Render.pulled ~domains:2))));
    Alcotest.test_case "with_pool: the loops of a command share one pool, torn down after" `Quick (fun () ->
        let workers () = other_domains (Render.parallel ~domains:2) in
        let one d = match d with [ d ] -> d | _ -> Alcotest.failf "expected one worker domain, got %d" (List.length d) in
        let a, b = Render.with_pool ~domains:2 (fun () -> (one (workers ()), one (workers ()))) in
        Alcotest.(check int) "the same worker in both loops" a b;
        (* outside it, each loop sets up (and ends) a pool of its own *)
        let c = one (workers ()) and d = one (workers ()) in
        Alcotest.(check bool) "a new worker a loop" true (c <> d && c <> a && d <> a);
        (* an exception ends the pool; the next command's pool works *)
        (match Render.with_pool ~domains:2 (fun () -> ignore (workers ()); failwith "stop") with
         | () -> Alcotest.fail "no exception"
         | exception Failure _ -> ());
        let e = Render.with_pool ~domains:2 (fun () -> one (workers ())) in
        Alcotest.(check bool) "a fresh worker" true (e <> a && e <> c && e <> d));
    Alcotest.test_case "with_pool: more domains than cores start at the first loop" `Quick (fun () ->
        (* domain ids grow: a domain spawned between [with_pool] and the
           first loop tells which came first *)
        let probe () = Domain.join (Domain.spawn (fun () -> (Domain.self () :> int))) in
        let over = Domain.recommended_domain_count () + 2 in
        let ids d =
          Render.with_pool ~domains:d (fun () ->
              let p = probe () in
              let a = other_domains (Render.parallel ~domains:d) in
              let p2 = probe () in
              (p, a, p2, other_domains (Render.parallel ~domains:d)))
        in
        let p, a, p2, b = ids over in
        Alcotest.(check bool) "workers spawned after the probe" true (a <> [] && List.for_all (fun w -> w > p) a);
        (* the second loop's workers are the pool's, spawned before the
           second probe (not every worker need take part in a loop) *)
        Alcotest.(check bool) "the second loop on the same pool" true
          (b <> [] && List.for_all (fun w -> w > p && w < p2) b);
        if Domain.recommended_domain_count () >= 2 then begin
          let p, a, _, _ = ids 2 in
          Alcotest.(check bool) "with a core each, workers are there before" true
            (a <> [] && List.for_all (fun w -> w < p) a)
        end);
    Alcotest.test_case "with_pool: 2 domains give the images of 1" `Quick (fun () ->
        let text = default_scene () in
        let a = Helpers.render_whitted ~domains:1 ~width:48 ~height:36 text in
        let b, c =
          Render.with_pool ~domains:2 (fun () ->
              let b = Helpers.render_whitted ~domains:2 ~width:48 ~height:36 text in
              (b, Helpers.render_whitted ~domains:2 ~width:48 ~height:36 text))
        in
        same_images a b;
        same_images a c);
    Alcotest.test_case "whitted: 1 and 2 domains give identical images" `Quick (fun () ->
        let text = default_scene () in
        let a = Helpers.render_whitted ~domains:1 ~width:48 ~height:36 text in
        let b = Helpers.render_whitted ~domains:2 ~width:48 ~height:36 text in
        same_images a b);
    Alcotest.test_case "mc: 1 and 2 domains give identical images" `Quick (fun () ->
        let s = Path.prepare (Helpers.compile_string (default_scene ())) in
        let r d =
          Render.image ~domains:d ~width:24 ~height:18
            (Path.pixel s ~width:24 ~height:18 ~seed:7 ~spp:4 ~max_depth:6)
        in
        same_images (r 1) (r 2));
    Alcotest.test_case "mc: the seed changes the noise" `Quick (fun () ->
        let s = Path.prepare (Helpers.compile_string (default_scene ())) in
        let r seed = Path.pixel s ~width:24 ~height:18 ~seed ~spp:2 ~max_depth:6 12 12 in
        Alcotest.(check bool) "differs" true (r 1 <> r 2));
    Alcotest.test_case "a mirror at trace level 1 is black (max_trace_level 1)" `Quick (fun () ->
        let img =
          Helpers.render_whitted ~width:1 ~height:1
            "#version 3.7; global_settings { max_trace_level 1 } background { rgb 1 }\n\
             plane { -z, -1 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }"
        in
        let r, _, _ = Helpers.pixel img 0 0 in
        Alcotest.(check (float 0.)) "black" 0. r);
    Alcotest.test_case "two facing mirrors: levels 1,2,3,5 give 0.1, 0.15, 0.175, 0.19375" `Quick (fun () ->
        (* pov-facts 5.7: reflection 0.5, ambient 0.1, white *)
        List.iter
          (fun (level, expected) ->
            let img =
              Helpers.render_whitted ~width:1 ~height:1
                (Printf.sprintf
                   "#version 3.7; global_settings { max_trace_level %d }\n\
                    camera { location <0,0,0> direction z }\n\
                    plane { -z, -1 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 0.5 } }\n\
                    plane { z, -1 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 0.5 } }"
                   level)
            in
            let r, _, _ = Helpers.pixel img 0 0 in
            Alcotest.(check (float 1e-9)) (Printf.sprintf "level %d" level) expected r)
          [ (1, 0.1); (2, 0.15); (3, 0.175); (5, 0.19375) ]);
  ]

(* The rendering domains' minor heaps: grown for a pixel function that
   allocates (fewer collections, each a stop of all domains), left alone
   for one that does not (growing is itself a collection), and the
   calling domain's own size back afterwards. *)
let heap_policy () =
  let own = (Gc.get ()).minor_heap_size in
  let largest garbage =
    let seen = Atomic.make 0 in
    let sink = ref [] in
    ignore
      (Render.image_into ~domains:2 ~width:256 ~height:256 (fun x y out ->
           if garbage then sink := List.init 16 (fun i -> i + x + y);
           (* looked at once a tile: [Gc.get] makes a record *)
           if x land 15 = 15 && y land 15 = 15 then begin
             let h = (Gc.get ()).minor_heap_size in
             if h > Atomic.get seen then Atomic.set seen h
           end;
           Color.acc_set out 0. 0. 0.));
    ignore (Sys.opaque_identity !sink);
    Atomic.get seen
  in
  let quiet = largest false and busy = largest true in
  Alcotest.(check int) "not grown without allocation" own quiet;
  Alcotest.(check bool) "grown for an allocating pixel function" true (busy >= 1024 * 1024);
  Alcotest.(check int) "the calling domain's size back" own (Gc.get ()).minor_heap_size

(* The 8-bit frame a PNG or PPM render fills: the bytes of the float
   frame quantized afterwards, for any value a pixel may hold (NaN,
   below 0, above 1, the default scene's), any encoding, whole images
   and regions, one domain or two. *)
let rgb8_frame () =
  let odd x y c =
    let h = Hashtbl.hash (x, y) in
    let v k = match (h lsr k) land 7 with 0 -> nan | 1 -> -0.25 | 2 -> 1.5 | 3 -> 1. | 4 -> 0. | _ -> float ((h lsr (k + 3)) land 1023) /. 1023. in
    Color.acc_set c (v 0) (v 13) (v 26)
  in
  let scene = Helpers.compile_string (default_scene ()) in
  let width = 37 and height = 29 in
  let shaded = Whitted.pixel_into scene ~width ~height in
  List.iter
    (fun (name, f) ->
      List.iter
        (fun enc ->
          List.iter
            (fun (domains, region) ->
              let a = Image.to_rgb8 enc (Render.image_into ~domains ?region ~width ~height f) in
              let b = Render.rgb8_into ~domains ?region ~width ~height enc f in
              if a.w <> b.w || a.h <> b.h || not (Bytes.equal a.data b.data) then
                Alcotest.failf "%s, %d domains%s: the 8-bit frame differs" name domains
                  (if region = None then "" else ", region"))
            [ (1, None); (2, None); (2, Some { Render.x0 = 5; y0 = 17; x1 = 36; y1 = 29 }) ])
        [ Image.Srgb; Image.Identity; Image.Gamma_srgb 2.2 ])
    [ ("arbitrary values", odd); ("default scene", shaded) ]

let tests = ("render", units @ [ Alcotest.test_case "8-bit frame = the float frame quantized" `Quick rgb8_frame; Alcotest.test_case "minor heaps grow only where pixels allocate" `Quick heap_policy ])
