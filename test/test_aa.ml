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

let tests =
  ( "aa",
    [
      Alcotest.test_case "supersampling grid" `Quick supersample;
      Alcotest.test_case "encoded threshold" `Quick threshold;
      Alcotest.test_case "1 vs 2 domains" `Quick determinism;
    ] )
