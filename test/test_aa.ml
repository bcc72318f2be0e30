(* Anti-aliasing: POV-Ray's method 1 without jitter (pov-facts.md 7). *)
open Camlray

(* a vertical edge at x = e inside pixel 0: black left of it, white right *)
let edge e px _py = if px < e then Color.black else Color.white

let supersample () =
  let ss e = (Aa.supersample ~depth:3 (edge e) 0 0 (edge e 0.5 0.5)).r in
  Scn.close "edge at 0.3" 0.7 (ss 0.3);
  Scn.close "edge at 0.6" 0.3 (ss 0.6);
  Scn.close "edge at 0.1" 1.0 (ss 0.1)

let threshold () =
  let a = Aa.encode (Color.gray 0.4) and b = Aa.encode (Color.gray 0.5) in
  Alcotest.(check bool) "0.4 vs 0.5 triggers at 0.19" true (Aa.differs 0.19 a b);
  Alcotest.(check bool) "0.4 vs 0.5 does not trigger at 0.2" false (Aa.differs 0.2 a b)

let scene =
  "camera { location <0, 1, -4> look_at <0, 0.6, 0> }\n\
   light_source { <-3, 5, -4>, rgb 1 }\n\
   plane { y, 0 pigment { checker rgb 1, rgb <0.1,0.2,0.6> scale 0.4 } }\n\
   sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.7 } }"

let render domains =
  let s = Scn.compile scene in
  Aa.render ~domains ~width:70 ~height:45 ~threshold:0.3 ~depth:3
    (Whitted.sample s ~width:70 ~height:45)

let determinism () =
  let a = render 1 and b = render 2 in
  let same = ref true and changed = ref 0 in
  let plain = Scn.compile scene in
  for y = 0 to 44 do
    for x = 0 to 69 do
      if Image.get_r a x y <> Image.get_r b x y || Image.get_g a x y <> Image.get_g b x y
         || Image.get_b a x y <> Image.get_b b x y then same := false;
      if Image.get_r a x y <> (Whitted.pixel plain ~width:70 ~height:45 x y).r then incr changed
    done
  done;
  Alcotest.(check bool) "1 and 2 domains give the same bits" true !same;
  Alcotest.(check bool) "some pixels were supersampled" true (!changed > 20)

(* The block buffers hold samples flat: an anti-aliased render keeps no
   young colour in an older block, so minor collections promote nothing
   per pixel (colours kept in arrays of records were promoted: some 8
   words per pixel, and the major collector then marked and swept them).
   The sample function makes garbage, so that collections happen
   mid-block. *)
let promotion () =
  let sample px py =
    for i = 1 to 40 do
      ignore (Sys.opaque_identity (ref i))
    done;
    Color.make (Float.rem px 7. /. 7.) (Float.rem py 5. /. 5.) 0.5
  in
  let width = 256 and height = 256 in
  ignore (Aa.render ~domains:1 ~width ~height ~threshold:0.1 ~depth:2 sample);
  let before = (Gc.quick_stat ()).promoted_words in
  let collections = (Gc.quick_stat ()).minor_collections in
  ignore (Aa.render ~domains:1 ~width ~height ~threshold:0.1 ~depth:2 sample);
  let s = Gc.quick_stat () in
  let per_pixel = (s.promoted_words -. before) /. float (width * height) in
  Alcotest.(check bool) "minor collections ran during the render" true (s.minor_collections - collections > 5);
  if per_pixel > 0.05 then Alcotest.failf "%.3f words promoted per pixel (at most 0.05; %d collections)" per_pixel (s.minor_collections - collections)

let tests =
  ( "aa",
    [
      Alcotest.test_case "supersampling grid" `Quick supersample;
      Alcotest.test_case "encoded threshold" `Quick threshold;
      Alcotest.test_case "1 vs 2 domains" `Quick determinism;
      Alcotest.test_case "nothing promoted per pixel" `Quick promotion;
    ] )
