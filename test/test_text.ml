(* TrueType text: the font's tables against facts read from the file
   independently (unitsPerEm, glyph ids, kerning, metrics), outlines'
   winding, hits on the extruded glyphs' surfaces with outward normals,
   and damaged font files refused with a message. Runs where Debian's
   povray fonts are installed. *)
open Camlray

let font_file = "/usr/share/povray-3.7/include/timrom.ttf"
let have_font () = Sys.file_exists font_file
let font = lazy (Ttf.read font_file)

let with_font f () = if have_font () then f (Lazy.force font) else print_endline "no timrom.ttf: skipped"

let facts =
  Alcotest.test_case "timrom.ttf: units, glyph ids, kerning, metrics" `Quick
    (with_font (fun f ->
         Alcotest.(check int) "unitsPerEm" 1000 (Ttf.units_per_em f);
         Alcotest.(check int) "A" 34 (Ttf.glyph_index f (Char.code 'A'));
         Alcotest.(check int) "V" 55 (Ttf.glyph_index f (Char.code 'V'));
         Alcotest.(check int) "kerning A V" (-187) (Ttf.kerning f 34 55);
         Alcotest.(check int) "kerning V O" (-56) (Ttf.kerning f 55 48);
         Alcotest.(check int) "no kerning A A" 0 (Ttf.kerning f 34 34);
         Alcotest.(check int) "advance of A" 750 (Ttf.advance f 34);
         Alcotest.(check int) "lsb of A" 6 (Ttf.lsb f 34)))

let o_ring =
  Alcotest.test_case "O: its ring is inside, its hole and the outside are not" `Quick
    (with_font (fun f ->
         let t = Text.make f "O" ~thickness:1. ~offset:Vec3.zero in
         let lo, hi = Text.bounds t in
         let cx = (lo.x +. hi.x) /. 2. and cy = (lo.y +. hi.y) /. 2. in
         Alcotest.(check int) "hole" 0 (Text.winding t cx cy);
         Alcotest.(check bool) "ring" true (Text.winding t (lo.x +. 0.03) cy <> 0);
         Alcotest.(check int) "outside" 0 (Text.winding t (hi.x +. 0.1) cy);
         Alcotest.(check bool) "inside between the faces" true (Text.inside t (lo.x +. 0.03) cy 0.5);
         Alcotest.(check bool) "not beyond the back face" false (Text.inside t (lo.x +. 0.03) cy 1.5)))

(* a ray from in front of "AVTo" aimed at a random point near it *)
let gray =
  QCheck.Gen.(
    map2
      (fun (ox, oy, oz) (tx, ty, tz) ->
        Ray.make (Vec3.make ox oy oz) (Vec3.sub (Vec3.make tx ty tz) (Vec3.make ox oy oz)))
      (triple (float_range (-2.) 4.) (float_range (-2.) 3.) (float_range (-5.) (-1.)))
      (triple (float_range (-0.2) 2.6) (float_range (-0.3) 1.) (float_range 0. 0.3)))

let surface =
  QCheck.Test.make ~name:"text: hits lie on the boundary, normals point out" ~count:2000
    (QCheck.make ~print:(fun (r : Ray.t) -> Vec3.to_string r.origin ^ " -> " ^ Vec3.to_string r.dir) gray)
    (fun r ->
      if not (have_font ()) then true
      else begin
        let t = Text.make (Lazy.force font) "AVTo" ~thickness:0.25 ~offset:Vec3.zero in
        let s = Shape.Text t in
        let h = Hit.create infinity in
        if not (Shape.hit s r 1e-9 h) then true
        else begin
          let p = Ray.at r h.t in
          let n = Shape.normal s p h in
          let e = 1e-6 in
          let a = Vec3.madd p e n and b = Vec3.madd p (-.e) n in
          (* a step out along the normal leaves the solid, a step in enters
             it (an edge may have neither side within the step: skipped) *)
          let out_ok = not (Text.inside t a.x a.y a.z) and in_ok = Text.inside t b.x b.y b.z in
          if out_ok && in_ok then true
          else if Float.abs (Vec3.dot n r.dir) < 1e-3 *. Vec3.length r.dir then true
          else QCheck.Test.fail_reportf "at %s (id %g) normal %s: outside %b inside %b" (Vec3.to_string p) h.id
              (Vec3.to_string n) out_ok in_ok
        end
      end)

(* damaged fonts: cut short or with bytes overwritten, then every glyph
   read: a Failure with a message, nothing else *)
let damaged =
  QCheck.Test.make ~name:"damaged font files fail with a message" ~count:300
    QCheck.(pair (int_bound 40000) (list_size (Gen.int_bound 8) (pair (int_bound 40000) (int_bound 255))))
    (fun (cut, pokes) ->
      if not (have_font ()) then true
      else begin
        let d = In_channel.with_open_bin font_file In_channel.input_all in
        let b = Bytes.of_string (String.sub d 0 (min cut (String.length d))) in
        List.iter (fun (i, v) -> if i < Bytes.length b then Bytes.set b i (Char.chr v)) pokes;
        match Ttf.parse (Bytes.to_string b) with
        | exception Failure _ -> true
        | f -> (
            try
              for c = 0 to 255 do
                ignore (Text.make f (String.make 1 (Char.chr c)) ~thickness:0.1 ~offset:Vec3.zero)
              done;
              true
            with Failure _ -> true)
      end)

(* text { internal N ... } is POV-Ray's built-in font N: the same picture
   as the font file Debian installs (POV-Ray 3.7's own renders of the two
   are identical, pixel for pixel) *)
let internal_fonts =
  Alcotest.test_case "internal 0-3 are povlogo, timrom, cyrvetic, crystal" `Quick (fun () ->
      if not (have_font ()) then print_endline "no POV-Ray fonts: skipped"
      else begin
        let scene font =
          Printf.sprintf
            "camera { location <1, 0.4, -3> look_at <1, 0.4, 0> }\nlight_source { <0, 2, -5> rgb 1 }\n\
             text { %s \"AgS\" 0.2, 0 pigment { rgb 1 } }\n" font
        in
        let img s = Helpers.render_whitted ~width:48 ~height:24 (scene s) in
        List.iteri
          (fun n file ->
            let a = img (Printf.sprintf "internal %d" n) and b = img (Printf.sprintf "ttf %S" file) in
            let lit = ref 0 in
            for y = 0 to 23 do
              for x = 0 to 47 do
                if Helpers.pixel a x y <> Helpers.pixel b x y then Alcotest.failf "internal %d differs from %s" n file;
                let r, _, _ = Helpers.pixel a x y in
                if r > 0.1 then incr lit
              done
            done;
            if !lit < 20 then Alcotest.failf "internal %d: only %d lit pixels" n !lit)
          [ "povlogo.ttf"; "timrom.ttf"; "cyrvetic.ttf"; "crystal.ttf" ];
        match Camlray_lang.Parse.string "text { internal 4 \"A\" 1, 0 }" with
        | Error d ->
            let m = Camlray_lang.Diag.to_string d in
            if not (String.length m > 0 && Str.string_match (Str.regexp ".*1:17: error: POV-Ray's internal fonts are 0 to 3") m 0)
            then Alcotest.failf "unexpected message %s" m
        | Ok _ -> Alcotest.fail "internal 4 accepted"
      end)

(* global_settings { charset }: POV-Ray 3.7 (checked with its renders)
   puts a space for each byte past ASCII by default (charset ascii),
   decodes UTF-8 with charset utf8, and refuses text under charset sys on
   this platform *)
let charset =
  Alcotest.test_case "charset ascii, utf8, sys" `Quick
    (with_font (fun f ->
         let glyphs settings str =
           let src =
             Printf.sprintf "global_settings { %s }\ntext { ttf \"timrom.ttf\" \"%s\" 0.1, 0 }\n" settings str
           in
           match Camlray_lang.Parse.string src with
           | Ok { Camlray_lang.Sdl.items; _ } -> (
               match
                 List.find_map
                   (function
                     | Camlray_lang.Sdl.Object { shape = Camlray_lang.Sdl.Text { glyphs; _ }; _ } -> Some glyphs
                     | _ -> None)
                   items
               with
               | Some g -> g
               | None -> Alcotest.fail "no text")
           | Error d -> Alcotest.failf "%s" (Camlray_lang.Diag.to_string d)
         in
         let same what a b =
           Alcotest.(check int) (what ^ ": glyphs") (Text.glyph_count a) (Text.glyph_count b);
           let (l1 : Vec3.t), (h1 : Vec3.t) = Text.bounds a and (l2 : Vec3.t), (h2 : Vec3.t) = Text.bounds b in
           Alcotest.(check (list (float 1e-12))) (what ^ ": bounds") [ l1.x; l1.y; h1.x; h1.y ] [ l2.x; l2.y; h2.x; h2.y ]
         in
         let codes c = Text.make_codes f c ~thickness:0.1 ~offset:Vec3.zero in
         same "ascii by default: a space for each byte of the copyright sign" (glyphs "assumed_gamma 1" "A\xc2\xa9B") (codes [| 65; 32; 32; 66 |]);
         same "charset ascii" (glyphs "charset ascii" "A\xc2\xa9B") (codes [| 65; 32; 32; 66 |]);
         same "charset utf8: one copyright sign" (glyphs "charset utf8" "A\xc2\xa9B") (codes [| 65; 169; 66 |]);
         if Ttf.glyph_index f 169 = 0 then Alcotest.fail "timrom.ttf has no copyright sign: the test shows nothing";
         let err src sub =
           match Camlray_lang.Parse.string src with
           | Ok _ -> Alcotest.failf "accepted: %s" src
           | Error d ->
               let m = Camlray_lang.Diag.to_string d in
               if not (Scn.contains m sub) then Alcotest.failf "message %S lacks %S" m sub
         in
         err "global_settings { charset sys }\ntext { ttf \"timrom.ttf\" \"A\" 0.1, 0 }" "2:23: error: charset sys";
         err "global_settings { charset utf8 }\ntext { ttf \"timrom.ttf\" \"A\xc3\" 0.1, 0 }" "2:27: error: invalid UTF-8 input";
         err "global_settings { charset latin1 }" "1:27: error: charset takes ascii, utf8 or sys"))

let tests = ("text", [ facts; o_ring; internal_fonts; charset ] @ List.map QCheck_alcotest.to_alcotest [ surface; damaged ])
