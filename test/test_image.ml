open Camlray

(* {1 Helpers} *)

(* A fresh empty folder, removed with its files afterwards. *)
let with_tmpdir f =
  let name =
    Printf.sprintf "camlray-test-%d-%06x" (Unix.getpid ())
      (Random.bits () land 0xFFFFFF)
  in
  let dir = Filename.concat (Filename.get_temp_dir_name ()) name in
  Unix.mkdir dir 0o755;
  let cleanup () =
    Array.iter (fun n -> Sys.remove (Filename.concat dir n)) (Sys.readdir dir);
    Unix.rmdir dir
  in
  Fun.protect ~finally:cleanup (fun () -> f dir)

let files dir = List.sort compare (Array.to_list (Sys.readdir dir))

let write_file path s =
  Out_channel.with_open_bin path (fun oc -> output_string oc s)

let read_file path = In_channel.with_open_bin path In_channel.input_all

let rgb8 w h l : Image.rgb8 =
  { w; h; data = Bytes.of_seq (Seq.map Char.chr (List.to_seq l)) }

let bytes_of (im : Image.rgb8) =
  List.init (Bytes.length im.data) (Bytes.get_uint8 im.data)

let check_rgb8 msg (exp : Image.rgb8) (got : Image.rgb8) =
  Alcotest.(check (pair int int)) (msg ^ " size") (exp.w, exp.h) (got.w, got.h);
  Alcotest.(check string)
    (msg ^ " data") (Bytes.to_string exp.data) (Bytes.to_string got.data)

let contains s sub =
  let n = String.length sub in
  let rec go i =
    i + n <= String.length s && (String.sub s i n = sub || go (i + 1))
  in
  go 0

(* CRC-32 bit by bit, independent of the table-driven one under test. *)
let bitwise_crc32 s =
  let c = ref 0xFFFFFFFF in
  String.iter
    (fun ch ->
      c := !c lxor Char.code ch;
      for _ = 1 to 8 do
        c := (!c lsr 1) lxor if !c land 1 = 1 then 0xEDB88320 else 0
      done)
    s;
  !c lxor 0xFFFFFFFF

(* PNGs built by hand, so tests can make any colour type and any damage
   with valid CRCs: [raw] (the filtered scanlines) goes into stored
   (uncompressed) deflate blocks in a zlib stream. *)
let zlib_stored raw =
  let n = String.length raw and b = Buffer.create (String.length raw + 64) in
  Buffer.add_string b "\x78\x01";
  let rec blocks pos =
    let len = min 65535 (n - pos) in
    Buffer.add_uint8 b (if pos + len = n then 1 else 0);
    Buffer.add_uint16_le b len;
    Buffer.add_uint16_le b (len lxor 0xFFFF);
    Buffer.add_string b (String.sub raw pos len);
    if pos + len < n then blocks (pos + len)
  in
  blocks 0;
  let a = ref 1 and c = ref 0 in
  String.iter
    (fun ch ->
      a := (!a + Char.code ch) mod 65521;
      c := (!c + !a) mod 65521)
    raw;
  Buffer.add_int32_be b (Int32.of_int ((!c lsl 16) lor !a));
  Buffer.contents b

let png_chunk typ data =
  let b = Buffer.create 64 in
  Buffer.add_int32_be b (Int32.of_int (String.length data));
  Buffer.add_string b typ;
  Buffer.add_string b data;
  Buffer.add_int32_be b (Int32.of_int (bitwise_crc32 (typ ^ data)));
  Buffer.contents b

let hand_png ?(interlace = 0) ?(before = []) ~w ~h ~ct ~depth idat =
  let ihdr = Bytes.create 13 in
  Bytes.set_int32_be ihdr 0 (Int32.of_int w);
  Bytes.set_int32_be ihdr 4 (Int32.of_int h);
  List.iteri
    (fun i v -> Bytes.set_uint8 ihdr (8 + i) v)
    [ depth; ct; 0; 0; interlace ];
  String.concat ""
    ([ "\x89PNG\r\n\x1a\n"; png_chunk "IHDR" (Bytes.to_string ihdr) ]
    @ List.map (fun (t, d) -> png_chunk t d) before
    @ [ png_chunk "IDAT" idat; png_chunk "IEND" "" ])

(* {1 SSIM reference pairs}

   Generated the same way by a Python script that fed them to
   scikit-image 0.26.0:
   structural_similarity(Y_a, Y_b, gaussian_weights=True, sigma=1.5,
   use_sample_covariance=False, data_range=255), with Y the float luma
   0.2126 R + 0.7152 G + 0.0722 B. *)

let lcg seed =
  let s = ref seed in
  fun () ->
    s := ((!s * 1103515245) + 12345) land 0x7FFFFFFF;
    (!s lsr 16) land 0xFF

let clamp v = max 0 (min 255 v)

let ssim_pair k : Image.rgb8 * Image.rgb8 =
  let pair w h a b = ({ Image.w; h; data = a }, { Image.w; h; data = b }) in
  let noisy g range a =
    Bytes.map
      (fun c -> Char.chr (clamp (Char.code c + (g () mod range) - (range / 2))))
      a
  in
  match k with
  | 1 ->
      (* random pixels, and the same plus noise in -20..20 *)
      let g = lcg 1 and w, h = (32, 24) in
      let a = Bytes.init (w * h * 3) (fun _ -> Char.chr (g ())) in
      pair w h a (noisy g 41 a)
  | 2 ->
      (* two unrelated random images, odd sizes *)
      let g = lcg 2 and w, h = (17, 13) in
      let a = Bytes.init (w * h * 3) (fun _ -> Char.chr (g ())) in
      let b = Bytes.init (w * h * 3) (fun _ -> Char.chr (g ())) in
      pair w h a b
  | _ ->
      (* a gradient, and the same plus noise in -8..8 *)
      let g = lcg 3 and w, h = (40, 30) in
      let a =
        Bytes.init (w * h * 3) (fun i ->
            let x = i / 3 mod w and y = i / 3 / w in
            Char.chr (((x * 5) + (y * 3) + (i mod 3 * 40)) mod 256))
      in
      pair w h a (noisy g 17 a)

let skimage_ssim =
  [ (1, 0.9864261666272863); (2, 0.07554042431077942); (3, 0.9475172889387787) ]

(* {1 Tests} *)

let gen_rgb8 =
  QCheck.Gen.(
    let* w = oneof [ return 1; int_range 1 40 ] in
    let* h = oneof [ return 1; int_range 1 20 ] in
    let* data = bytes_size (return (w * h * 3)) in
    return { Image.w; h; data })

let arb_rgb8 =
  QCheck.make
    ~print:(fun (im : Image.rgb8) -> Printf.sprintf "%dx%d" im.w im.h)
    gen_rgb8

let arb_tall =
  QCheck.make
    ~print:(fun (im : Image.rgb8) -> Printf.sprintf "%dx%d" im.w im.h)
    QCheck.Gen.(
      let* w = int_range 1 9 in
      let* h = int_range 65 200 in
      (* smooth rows, as renders are, and noise *)
      let* noisy = bool in
      let* data = bytes_size (return (w * h * 3)) in
      if not noisy then Bytes.iteri (fun i _ -> Bytes.set_uint8 data i (i / 7 land 255)) data;
      return { Image.w; h; data })

let read_all f = In_channel.with_open_bin f In_channel.input_all

let round_trip write name (im : Image.rgb8) =
  with_tmpdir (fun dir ->
      let path = Filename.concat dir name in
      write path im;
      let back = Image.read path in
      back.w = im.w && back.h = im.h
      && Bytes.equal back.data im.data
      && files dir = [ name ])

let props =
  [
    QCheck.Test.make ~count:150 arb_rgb8
      ~name:"PNG write -> read is byte-identical, no temp file left"
      (round_trip (fun p im -> Image.write_png p im) "im.png");
    QCheck.Test.make ~count:50 arb_rgb8
      ~name:"PPM write -> read is byte-identical"
      (round_trip Image.write_ppm "im.ppm");
    (* taller than one 64-row band: the bands' deflate runs are joined *)
    QCheck.Test.make ~count:25 arb_tall
      ~name:"PNG of several bands: read back identical, same file on 1 and 3 domains"
      (fun im ->
        with_tmpdir (fun dir ->
            let a = Filename.concat dir "a.png" and b = Filename.concat dir "b.png" in
            Image.write_png a im;
            Image.write_png ~par:(Render.parallel ~domains:3) b im;
            let back = Image.read a in
            Bytes.equal back.data im.data && read_all a = read_all b));
    QCheck.Test.make ~count:200
      QCheck.(pair string string)
      ~name:"adler32_combine of two parts = adler32 of the whole"
      (fun (a, b) ->
        let whole = a ^ b in
        Png_codec.adler32_combine (Png_codec.adler32 a 0 (String.length a)) (Png_codec.adler32 b 0 (String.length b))
          (String.length b)
        = Png_codec.adler32 whole 0 (String.length whole));
    QCheck.Test.make ~count:2000
      QCheck.(pair (oneof_list [ Image.Srgb; Image.Identity; Image.Gamma_srgb 2.2; Image.Gamma_srgb 0.45 ])
                (make ~print:string_of_float Gen.(oneof [ float_range (-0.1) 1.1; float; float_range 0. 0.01 ])))
      ~name:"to_rgb8 (by table) = the formula, for any float"
      (fun (enc, v) ->
        let img = Image.create 1 1 in
        Image.set img 0 0 v (Float.succ v) (Float.pred v);
        let im = Image.to_rgb8 enc img in
        List.for_all2 (fun i v -> Bytes.get_uint8 im.data i = Image.quantize enc v)
          [ 0; 1; 2 ] [ v; Float.succ v; Float.pred v ]);
  ]

(* The table starts each value's search at the level of its part of
   [0, 1) (parts of 1/8192): every part's ends and their neighbours, and
   a sweep of [0, 1] through every level, agree with the formula. *)
let table_edges =
  Alcotest.test_case "to_rgb8 = the formula at every part's ends and across [0, 1]" `Quick (fun () ->
      let values =
        List.concat
          [ List.concat_map (fun b -> let x = float b /. 8192. in [ Float.pred x; x; Float.succ x ])
              (List.init 8193 Fun.id);
            List.init 200_001 (fun i -> float i /. 200_000.);
            [ 0.; -0.; -1e-300; 1.; Float.pred 1.; Float.succ 1.; infinity; neg_infinity; nan ] ]
      in
      let n = List.length values in
      let img = Image.create n 1 in
      List.iteri (fun x v -> Image.set img x 0 v v v) values;
      List.iter
        (fun enc ->
          let im = Image.to_rgb8 enc img in
          List.iteri
            (fun x v ->
              let got = Bytes.get_uint8 im.data (3 * x) and want = Image.quantize enc v in
              if got <> want then Alcotest.failf "%h: table %d, formula %d" v got want)
            values)
        [ Image.Srgb; Image.Identity; Image.Gamma_srgb 2.2; Image.Gamma_srgb 0.45 ])

let encoding_tests =
  [
    Alcotest.test_case "srgb_encode known values" `Quick (fun () ->
        let check = Alcotest.(check (float 1e-12)) in
        check "0" 0. (Image.srgb_encode 0.);
        check "1" 1. (Image.srgb_encode 1.);
        check "linear part" (12.92 *. 0.001) (Image.srgb_encode 0.001);
        Alcotest.(check (float 1e-4)) "0.7" 0.85431 (Image.srgb_encode 0.7));
    Alcotest.test_case "srgb_encode is continuous at 0.0031308" `Quick
      (fun () ->
        let t = 0.0031308 in
        let lo = Image.srgb_encode t and hi = Image.srgb_encode (t +. 1e-12) in
        Alcotest.(check (float 1e-6)) "both branches meet" lo hi;
        Alcotest.(check (float 1e-6)) "value" 0.040449936 lo);
    Alcotest.test_case "to_rgb8 clips, rounds, maps NaN to 0" `Quick (fun () ->
        let vals =
          [ -0.5; 2.0; Float.nan; 0.5; 0.2; 100.4 /. 255.; Float.infinity;
            Float.neg_infinity; 0.7 ]
        in
        let img = Image.create (List.length vals) 1 in
        List.iteri (fun x v -> Image.set img x 0 v v v) vals;
        let reds (im : Image.rgb8) =
          List.init im.w (fun x -> Bytes.get_uint8 im.data (3 * x))
        in
        Alcotest.(check (list int))
          "identity"
          [ 0; 255; 0; 128; 51; 100; 255; 0; 179 ]
          (reds (Image.to_rgb8 Identity img));
        Alcotest.(check (list int))
          "srgb"
          [ 0; 255; 0; 188; 124; 168; 255; 0; 218 ]
          (reds (Image.to_rgb8 Srgb img)));
    Alcotest.test_case "Adler-32 known values (RFC 1950)" `Quick (fun () ->
        Alcotest.(check int) "Wikipedia" 0x11E60398 (Png_codec.adler32 "Wikipedia" 0 9);
        Alcotest.(check int) "empty" 1 (Png_codec.adler32 "" 0 0);
        (* past the 5552-byte reduction step: 10^5 bytes of 0xFF, by the
           definition: s1 = 1 + 255 n, s2 = n + 255 n (n+1) / 2, mod 65521 *)
        let n = 100_000 in
        let s1 = (1 + (255 * n)) mod 65521 and s2 = (n + (255 * n * (n + 1) / 2)) mod 65521 in
        Alcotest.(check int) "10^5 x 0xFF" ((s2 lsl 16) lor s1) (Png_codec.adler32 (String.make n '\xff') 0 n));
    Alcotest.test_case "to_rgb8 layout: row-major, row 0 at the top" `Quick
      (fun () ->
        let img = Image.create 2 2 in
        Image.set img 1 0 1. 0. 0.;
        Image.set img 0 1 0. 0. 1.;
        Alcotest.(check (list int))
          "bytes"
          [ 0; 0; 0; 255; 0; 0; 0; 0; 255; 0; 0; 0 ]
          (bytes_of (Image.to_rgb8 Identity img)));
  ]

let png_tests =
  [
    Alcotest.test_case "PNG 1x1 and odd width round trip" `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "a.png" in
            List.iter
              (fun im ->
                Image.write_png path im;
                check_rgb8 "round trip" im (Image.read path))
              [ rgb8 1 1 [ 1; 2; 3 ];
                rgb8 3 2 (List.init 18 (fun i -> 255 - (i * 13))) ]));
    Alcotest.test_case "PNG header: 8-bit RGB, non-interlaced, CRCs" `Quick
      (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "a.png" in
            Image.write_png ~text:[ ("Software", "camlray") ] path
              (rgb8 2 1 [ 0; 0; 0; 9; 9; 9 ]);
            let s = read_file path in
            let u32 i = Int32.to_int (String.get_int32_be s i) land 0xFFFFFFFF in
            Alcotest.(check string)
              "signature" "\x89PNG\r\n\x1a\n" (String.sub s 0 8);
            Alcotest.(check string) "IHDR first" "IHDR" (String.sub s 12 4);
            Alcotest.(check (list int))
              "w, h, depth, colour, compression, filter, interlace"
              [ 2; 1; 8; 2; 0; 0; 0 ]
              (u32 16 :: u32 20 :: List.init 5 (fun i -> Char.code s.[24 + i]));
            Alcotest.(check int)
              "IHDR CRC" (bitwise_crc32 (String.sub s 12 17)) (u32 29);
            Alcotest.(check string)
              "ends with IEND" "\000\000\000\000IEND\xae\x42\x60\x82"
              (String.sub s (String.length s - 12) 12)));
    Alcotest.test_case "tEXt round trip, in order" `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "t.png" in
            let text =
              [ ("Title", "A scene"); ("Comment", "line 1\nline 2\xe9");
                ("Software", "") ]
            in
            let im = rgb8 2 2 (List.init 12 (fun i -> i * 20)) in
            let check_text = Alcotest.(check (list (pair string string))) in
            Image.write_png ~text path im;
            check_text "text" text (Image.png_text path);
            check_rgb8 "pixels still readable" im (Image.read path);
            Image.write_png path im;
            check_text "no text" [] (Image.png_text path)));
    Alcotest.test_case "invalid tEXt entries are refused, nothing written"
      `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "t.png" in
            List.iter
              (fun kv ->
                match Image.write_png ~text:[ kv ] path (rgb8 1 1 [ 0; 0; 0 ]) with
                | () -> Alcotest.fail "accepted an invalid entry"
                | exception Invalid_argument _ -> ())
              [ ("", "x"); (String.make 80 'k', "x"); ("a\000b", "x");
                ("k", "a\000b") ];
            Alcotest.(check (list string)) "no files" [] (files dir)));
    Alcotest.test_case "PNG colour types, bit depths and interlacing" `Quick
      (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "h.png" in
            let reads msg exp png =
              write_file path png;
              check_rgb8 msg exp (Image.read path)
            in
            let png1 ?before ct depth raw =
              hand_png ?before ~w:1 ~h:1 ~ct ~depth (zlib_stored raw)
            in
            reads "grey 8" (rgb8 2 1 [ 7; 7; 7; 200; 200; 200 ])
              (hand_png ~w:2 ~h:1 ~ct:0 ~depth:8 (zlib_stored "\000\007\200"));
            reads "grey 16" (rgb8 1 1 [ 18; 18; 18 ]) (png1 0 16 "\000\018\052");
            reads "grey 1-bit"
              (rgb8 3 1 [ 255; 255; 255; 0; 0; 0; 255; 255; 255 ])
              (hand_png ~w:3 ~h:1 ~ct:0 ~depth:1 (zlib_stored "\000\xa0"));
            reads "grey + alpha" (rgb8 1 1 [ 9; 9; 9 ]) (png1 4 8 "\000\009\100");
            reads "RGBA, alpha dropped" (rgb8 1 1 [ 1; 2; 3 ])
              (png1 6 8 "\000\001\002\003\004");
            reads "RGB 16" (rgb8 1 1 [ 1; 2; 255 ])
              (png1 2 16 "\000\001\000\002\000\255\255");
            let plte = ("PLTE", "\010\020\030\040\050\060") in
            let pal before =
              hand_png ~before ~w:2 ~h:1 ~ct:3 ~depth:8 (zlib_stored "\000\001\000")
            in
            let expected = rgb8 2 1 [ 40; 50; 60; 10; 20; 30 ] in
            reads "palette" expected (pal [ plte ]);
            reads "palette with tRNS" expected (pal [ plte; ("tRNS", "\000") ]);
            (* Adam7, 2x2: pass 1 holds (0,0), pass 6 (1,0), pass 7 row 1 *)
            reads "interlaced" (rgb8 2 2 (List.init 12 (fun i -> i + 1)))
              (hand_png ~interlace:1 ~w:2 ~h:2 ~ct:2 ~depth:8
                 (zlib_stored
                    "\000\001\002\003\000\004\005\006\000\007\008\009\010\011\012"))));
    Alcotest.test_case "png_text rejects a non-PNG and a bad CRC" `Quick
      (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "x.png" in
            let png_text () = ignore (Image.png_text path) in
            write_file path "P6\n1 1\n255\n\000\000\000";
            Alcotest.check_raises "not png"
              (Failure (path ^ ": not a PNG file")) png_text;
            Image.write_png ~text:[ ("k", "v") ] path (rgb8 1 1 [ 0; 0; 0 ]);
            let s = Bytes.of_string (read_file path) in
            (* the tEXt chunk starts at 33; its value byte is at 43 *)
            Bytes.set s 43 'w';
            write_file path (Bytes.to_string s);
            Alcotest.check_raises "bad crc"
              (Failure (path ^ ": bad CRC in tEXt chunk")) png_text));
  ]

let ppm_tests =
  let read_string name s =
    with_tmpdir (fun dir ->
        let path = Filename.concat dir name in
        write_file path s;
        Image.read path)
  in
  [
    Alcotest.test_case "P6 with comments, maxval 255" `Quick (fun () ->
        check_rgb8 "p6"
          (rgb8 2 1 [ 1; 2; 3; 250; 251; 252 ])
          (read_string "a.ppm"
             "P6\n# a comment\n2 # inline\n1\n255\n\001\002\003\250\251\252"));
    Alcotest.test_case "P6 with maxval 65535 (16-bit big-endian)" `Quick
      (fun () ->
        check_rgb8 "p6 16" (rgb8 1 1 [ 0; 255; 128 ])
          (read_string "a.ppm" "P6 1 1 65535\n\000\000\255\255\128\000"));
    Alcotest.test_case "P3 with a comment and maxval 65535" `Quick (fun () ->
        check_rgb8 "p3"
          (rgb8 2 1 [ 0; 255; 128; 1; 0; 127 ])
          (read_string "b.ppm"
             "P3\n# made by hand\n2 1\n65535\n0 65535 32768\n257 128 32639\n"));
    Alcotest.test_case "P3 with maxval 15 scales with rounding" `Quick
      (fun () ->
        check_rgb8 "p3 15" (rgb8 1 1 [ 255; 119; 17 ])
          (read_string "c.ppm" "P3 1 1 15 15 7 1"));
    Alcotest.test_case "format is told by magic bytes, not extension" `Quick
      (fun () ->
        check_rgb8 "ppm named .png" (rgb8 1 1 [ 7; 8; 9 ])
          (read_string "x.png" "P3 1 1 255 7 8 9");
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "y.ppm" in
            Image.write_png path (rgb8 1 1 [ 4; 5; 6 ]);
            check_rgb8 "png named .ppm" (rgb8 1 1 [ 4; 5; 6 ]) (Image.read path)));
    Alcotest.test_case "bad files give a Failure naming the file" `Quick
      (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "bad" in
            let fails what s =
              write_file path s;
              match Image.read path with
              | _ -> Alcotest.failf "%s: accepted" what
              | exception Failure m ->
                  if not (String.starts_with ~prefix:(path ^ ": ") m) then
                    Alcotest.failf "%s: message %S does not name the file" what m
            in
            fails "unknown" "GIF89a";
            fails "truncated P6" "P6 2 2 255\n\000\000\000";
            fails "P3 over maxval" "P3 1 1 10 11 0 0";
            fails "P3 missing sample" "P3 1 1 10 1 0";
            fails "maxval too big" "P3 1 1 65536 1 0 0";
            let rgb_png raw = hand_png ~w:2 ~h:1 ~ct:2 ~depth:8 raw in
            let ok = rgb_png (zlib_stored "\000abcdef") in
            fails "PNG without IEND" (String.sub ok 0 (String.length ok - 12));
            fails "short image data" (rgb_png (zlib_stored "\000abcde"));
            fails "too much image data" (rgb_png (zlib_stored "\000abcdefg"));
            fails "bad filter type" (rgb_png (zlib_stored "\005abcdef"));
            fails "corrupt zlib" (rgb_png "\x78\x01garbage");
            fails "truncated zlib"
              (rgb_png (String.sub (zlib_stored "\000abcdef") 0 10));
            fails "palette without PLTE"
              (hand_png ~w:1 ~h:1 ~ct:3 ~depth:8 (zlib_stored "\000\000"));
            fails "unknown critical chunk"
              (hand_png ~before:[ ("ABCD", "") ] ~w:1 ~h:1 ~ct:2 ~depth:8
                 (zlib_stored "\000abc"));
            let corrupt = Bytes.of_string ok in
            Bytes.set corrupt 45 'X';
            fails "bad IDAT CRC" (Bytes.to_string corrupt);
            fails "PNG signature and half an IHDR"
              "\x89PNG\r\n\x1a\n\000\000\000\013IHDR";
            (* camlimages alone segfaults on this one *)
            let good = Filename.concat dir "good.png" in
            Image.write_png good (rgb8 8 8 (List.init 192 (fun i -> i)));
            let png = read_file good in
            fails "PNG cut inside IDAT" (String.sub png 0 (String.length png - 20));
            Sys.remove path;
            match Image.read path with
            | _ -> Alcotest.fail "read a missing file"
            | exception Failure m ->
                Alcotest.(check bool) "names the file" true (contains m path)));
  ]

let pfm_tests =
  [
    Alcotest.test_case "PFM header, size, little-endian, bottom row first"
      `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "a.pfm" in
            let img = Image.create 3 2 in
            Image.set img 0 1 0.25 (-1.5) 1e6;
            Image.set img 2 0 2.0 0. 0.;
            Image.write_pfm path img;
            let s = read_file path in
            let header = "PF\n3 2\n-1.0\n" in
            let hl = String.length header in
            Alcotest.(check string) "header" header (String.sub s 0 hl);
            Alcotest.(check int) "size" (hl + (3 * 2 * 12)) (String.length s);
            let f i = Int32.float_of_bits (String.get_int32_le s (hl + (4 * i))) in
            Alcotest.(check (list (float 0.)))
              "first pixel is (0, bottom row)" [ 0.25; -1.5; 1e6 ]
              [ f 0; f 1; f 2 ];
            Alcotest.(check (float 0.)) "top row comes last" 2.0 (f 15)));
  ]

let metric_tests =
  [
    Alcotest.test_case "PSNR hand-computed" `Quick (fun () ->
        let a = rgb8 4 3 (List.init 36 (fun i -> i * 7)) in
        Alcotest.(check (float 0.)) "identical" Float.infinity (Metrics.psnr a a);
        let b = { a with data = Bytes.copy a.data } in
        Bytes.set_uint8 b.data 5 (Bytes.get_uint8 b.data 5 + 1);
        Alcotest.(check (float 1e-9))
          "one byte off by one"
          (10. *. log10 (255. *. 255. /. (1. /. 36.)))
          (Metrics.psnr a b);
        let black = rgb8 1 1 [ 0; 0; 0 ] and white = rgb8 1 1 [ 255; 255; 255 ] in
        Alcotest.(check (float 1e-12)) "black/white" 0. (Metrics.psnr black white);
        Alcotest.check_raises "size mismatch"
          (Invalid_argument "Metrics.psnr: sizes differ (1x1 vs 4x3)") (fun () ->
            ignore (Metrics.psnr black a)));
    Alcotest.test_case "SSIM of identical images is 1" `Quick (fun () ->
        let a, b = ssim_pair 1 in
        Alcotest.(check (float 1e-12)) "a a" 1. (Metrics.ssim a a);
        Alcotest.(check (float 1e-12)) "b b" 1. (Metrics.ssim b b));
    Alcotest.test_case "SSIM is symmetric" `Quick (fun () ->
        List.iter
          (fun k ->
            let a, b = ssim_pair k in
            Alcotest.(check (float 1e-12)) "sym" (Metrics.ssim a b) (Metrics.ssim b a))
          [ 1; 2; 3 ]);
    Alcotest.test_case "SSIM matches scikit-image" `Quick (fun () ->
        List.iter
          (fun (k, expected) ->
            let a, b = ssim_pair k in
            Alcotest.(check (float 1e-9))
              (Printf.sprintf "pair %d" k) expected (Metrics.ssim a b))
          skimage_ssim);
    Alcotest.test_case "SSIM needs 11x11" `Quick (fun () ->
        let a = rgb8 10 11 (List.init 330 (fun _ -> 0)) in
        match Metrics.ssim a a with
        | _ -> Alcotest.fail "accepted 10x11"
        | exception Invalid_argument _ -> ());
    Alcotest.test_case "max_diff and diff_image" `Quick (fun () ->
        let a = rgb8 2 1 [ 0; 100; 200; 50; 50; 50 ]
        and b = rgb8 2 1 [ 10; 90; 255; 50; 0; 51 ] in
        Alcotest.(check int) "max_diff" 55 (Metrics.max_diff a b);
        Alcotest.(check int) "max_diff self" 0 (Metrics.max_diff a a);
        Alcotest.(check (list int))
          "gain 4" [ 40; 40; 220; 0; 200; 4 ]
          (bytes_of (Metrics.diff_image a b));
        Alcotest.(check (list int))
          "gain 10 clips" [ 100; 100; 255; 0; 255; 10 ]
          (bytes_of (Metrics.diff_image ~gain:10 a b)));
    Alcotest.test_case "side_by_side pads heights with black" `Quick (fun () ->
        let a = rgb8 1 2 [ 1; 1; 1; 2; 2; 2 ]
        and b = rgb8 2 1 [ 3; 3; 3; 4; 4; 4 ] in
        let s = Metrics.side_by_side [ a; b ] in
        Alcotest.(check (pair int int)) "size" (3, 2) (s.w, s.h);
        Alcotest.(check (list int))
          "pixels"
          [ 1; 1; 1; 3; 3; 3; 4; 4; 4; 2; 2; 2; 0; 0; 0; 0; 0; 0 ]
          (bytes_of s));
  ]

let atomic_tests =
  [
    Alcotest.test_case "a failing writer leaves the old file, no temp file"
      `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "keep.png" in
            write_file path "old contents";
            (match
               Image.write_atomic path (fun oc ->
                   output_string oc "new half-written";
                   failwith "boom")
             with
            | () -> Alcotest.fail "no exception"
            | exception Failure m ->
                Alcotest.(check bool) "names the path" true (contains m path);
                Alcotest.(check bool) "keeps the reason" true (contains m "boom"));
            Alcotest.(check string) "untouched" "old contents" (read_file path);
            Alcotest.(check (list string)) "no temp" [ "keep.png" ] (files dir);
            (* other exceptions pass through unchanged *)
            Alcotest.check_raises "Exit" Exit (fun () ->
                Image.write_atomic path (fun _ -> raise Exit));
            Alcotest.(check (list string))
              "still no temp" [ "keep.png" ] (files dir)));
    Alcotest.test_case "a successful write replaces the file" `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "f.txt" in
            write_file path "old";
            Image.write_atomic path (fun oc -> output_string oc "new");
            Alcotest.(check string) "replaced" "new" (read_file path);
            Alcotest.(check (list string)) "only it" [ "f.txt" ] (files dir)));
    Alcotest.test_case "a missing folder gives Sys_error and no file" `Quick
      (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat (Filename.concat dir "nope") "a.png" in
            (match Image.write_png path (rgb8 1 1 [ 0; 0; 0 ]) with
            | () -> Alcotest.fail "wrote into a missing folder"
            | exception Sys_error m ->
                Alcotest.(check bool) "names the path" true (contains m path));
            Alcotest.(check bool) "no file" false (Sys.file_exists path);
            Alcotest.(check (list string)) "nothing created" [] (files dir)));
  ]

(* JPEG: the frame's component count read from its markers (POV-Ray keeps
   a grey JPEG as grey, a colour one as colour), decoding through
   Image.read, and height fields from a colour JPEG by POV-Ray's 8-bit
   colour rule (red the high byte, green the low one) *)
let jpeg_tests =
  let seg m body = "\xFF" ^ String.make 1 (Char.chr m) ^ (let n = String.length body + 2 in String.init 2 (fun i -> Char.chr (if i = 0 then n lsr 8 else n land 0xFF))) ^ body in
  (* a frame header: precision 8, 16 x 8, [k] components of 3 bytes *)
  let sof m k = seg m ("\008\000\008\000\016" ^ String.make 1 (Char.chr k) ^ String.make (3 * k) '\001') in
  let soi = "\xFF\xD8" and app0 = seg 0xE0 "JFIF\000\001\001\000\000\001\000\001\000\000" in
  [
    Alcotest.test_case "jpeg_components reads the frame header" `Quick (fun () ->
        Alcotest.(check int) "grey baseline" 1 (Image.jpeg_components (soi ^ app0 ^ sof 0xC0 1));
        Alcotest.(check int) "colour progressive" 3 (Image.jpeg_components (soi ^ app0 ^ sof 0xC2 3));
        Alcotest.(check int) "after a Huffman table (C4 is not a frame)" 1
          (Image.jpeg_components (soi ^ seg 0xC4 "\000\001\002" ^ sof 0xC1 1));
        Alcotest.(check int) "fill bytes before a marker" 3 (Image.jpeg_components (soi ^ "\xFF\xFF" ^ sof 0xC0 3));
        Alcotest.check_raises "scan before any frame" (Failure "JPEG without a frame header") (fun () ->
            ignore (Image.jpeg_components (soi ^ seg 0xDA "\001")));
        Alcotest.check_raises "cut short" (Failure "truncated JPEG frame header") (fun () ->
            ignore (Image.jpeg_components (soi ^ "\xFF\xC0\000\011\008\000"))));
    Alcotest.test_case "a JPEG image_map and height field" `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "c.jpg" in
            let w = 16 and h = 8 in
            let img = Rgb24.create w h in
            for y = 0 to h - 1 do
              for x = 0 to w - 1 do
                Rgb24.set img x y ({ r = 200; g = 100 + (4 * x); b = 30 } : Rgb24.elt)
              done
            done;
            Jpeg.save path [ Images.Save_Quality 100 ] (Images.Rgb24 img);
            Alcotest.(check bool) "told apart by its first bytes" true (Image.is_jpeg (read_file path));
            Alcotest.(check int) "colour" 3 (Image.jpeg_components (read_file path));
            let im = Image.read path in
            Alcotest.(check (pair int int)) "size" (w, h) (im.w, im.h);
            (* libjpeg's decoding, near the colours written *)
            let b x y k = Char.code (Bytes.get im.data ((3 * ((y * w) + x)) + k)) in
            for x = 0 to w - 1 do
              if abs (b x 3 0 - 200) > 3 || abs (b x 3 1 - (100 + (4 * x))) > 3 then
                Alcotest.failf "pixel (%d, 3) decoded as (%d, %d)" x (b x 3 0) (b x 3 1)
            done;
            let hf = Hf_image.read path in
            Alcotest.(check (pair int int)) "height field size" (w, h) (hf.w, hf.h);
            for i = 0 to (w * h) - 1 do
              let r = Char.code (Bytes.get im.data (3 * i)) and g = Char.code (Bytes.get im.data ((3 * i) + 1)) in
              let expected = ((r * 256) + g) * 255 / 255 in
              (* of_rgb8: (r/255 * 256 + g/255) * 255 in single precision, truncated *)
              if abs (hf.v.(i) - expected) > 1 then
                Alcotest.failf "height %d: %d, red %d green %d give %d" i hf.v.(i) r g expected
            done;
            write_file path "\xFF\xD8\xFF\xE0garbage";
            match Image.read path with
            | _ -> Alcotest.fail "a damaged JPEG was read"
            | exception Failure m ->
                if not (contains m path) then Alcotest.failf "the message %S does not name the file" m));
  ]

(* GIF: colours through the palette (Image.read), indices and the
   palette's size, and as a height field POV-Ray's 8-bit indexed rule
   (index x 256) or, read as a POT file, a 16-bit height from the two
   halves' indices (high byte left) *)
let gif_tests =
  [
    Alcotest.test_case "a GIF image, its indices, as a height field and as POT" `Quick (fun () ->
        with_tmpdir (fun dir ->
            let path = Filename.concat dir "i.gif" in
            let img = Index8.create 4 1 in
            (* camlimages' Color (Camlray's is open here): its records by their types *)
            let cmap = img.colormap in
            cmap.max <- 255;
            cmap.map <- Array.init 256 (fun i : Rgb24.elt -> { r = i; g = 255 - i; b = 7 });
            List.iteri (fun x v -> Index8.set img x 0 v) [ 1; 2; 3; 4 ];
            Gif.save_image path [] (Images.Index8 img);
            Alcotest.(check bool) "told apart by its first bytes" true (Image.is_gif (read_file path));
            check_rgb8 "colours through the palette" (rgb8 4 1 [ 1; 254; 7; 2; 253; 7; 3; 252; 7; 4; 251; 7 ]) (Image.read path);
            let w, h, idx, n = Image.gif_indices path in
            Alcotest.(check (list int)) "indices" [ 4; 1; 1; 2; 3; 4 ] ([ w; h ] @ List.init 4 (fun i -> Char.code (Bytes.get idx i)));
            if n < 5 then Alcotest.failf "palette of %d entries" n;
            let hf = Hf_image.read path in
            Alcotest.(check (list int)) "heights: index x 256" [ 256; 512; 768; 1024 ] (Array.to_list hf.v);
            let pot = Hf_image.read ~pot:true path in
            Alcotest.(check (pair int int)) "POT: half as wide" (2, 1) (pot.w, pot.h);
            Alcotest.(check (list int)) "POT: left high byte, right low byte" [ (1 lsl 8) lor 3; (2 lsl 8) lor 4 ] (Array.to_list pot.v);
            write_file path "GIF89agarbage";
            match Image.read path with
            | _ -> Alcotest.fail "a damaged GIF was read"
            | exception Failure m -> if not (contains m path) then Alcotest.failf "the message %S does not name the file" m));
  ]

let tests =
  ( "image",
    (table_edges :: encoding_tests) @ png_tests @ ppm_tests @ pfm_tests @ metric_tests @ jpeg_tests @ gif_tests
    @ atomic_tests
    @ List.map QCheck_alcotest.to_alcotest props )
