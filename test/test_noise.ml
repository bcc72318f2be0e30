(* POV-Ray's noise (lib/noise.ml): its range and its continuity across
   the lattice's planes as properties, at random points, lattice planes'
   neighbours on both sides, negative zeros and coordinates up to 1e9
   (where the lattice index wraps); its values against POV-Ray's own
   (files written by POV-Ray 3.7, below). *)
open Camlray

let coordinate =
  let open QCheck.Gen in
  oneof_weighted
    [
      (6, float_range (-4.) 4.);
      (4, float_range (-300.) 300.);
      (2, map float_of_int (int_range (-600) 600));
      (* a lattice plane's neighbours, both sides *)
      (2, map2 (fun n up -> if up then Float.succ (float_of_int n) else Float.pred (float_of_int n))
            (int_range (-600) 600) bool);
      (1, oneof_list [ 0.; -0.; 1e-9; -1e-9; 255.5; 256.; -256.; 511.999 ]);
      (2, map2 (fun m e -> m *. (10. ** float_of_int e)) (float_range (-1.) 1.) (int_range 3 9));
    ]

let point = QCheck.Gen.triple coordinate coordinate coordinate
let print_point (x, y, z) = Printf.sprintf "(%h, %h, %h)" x y z
let arb_point = QCheck.make ~print:print_point point

(* every generator's noise in [0, 1] *)
let range_prop =
  QCheck.Test.make ~name:"Noise.noise: in [0, 1] for generators 1, 2, 3" ~count:20000 arb_point (fun (x, y, z) ->
      List.for_all
        (fun g ->
          let v = Noise.noise g x y z in
          (v >= 0. && v <= 1.) || QCheck.Test.fail_reportf "generator %d: %h" g v)
        [ 1; 2; 3 ])

(* the noise and DNoise are continuous: either side of a lattice plane
   (the two floats around an integer, in any of the three axes, negative
   ones included, where POV-Ray moves the lattice coordinate by 1 - 1e-10)
   they differ by next to nothing *)
let continuity_prop =
  let gen = QCheck.Gen.(pair (triple (int_range (-5000) 5000) (float_range (-50.) 50.) (float_range (-50.) 50.)) (int_range 0 2)) in
  QCheck.Test.make ~name:"Noise.noise, dnoise: continuous across the lattice's planes" ~count:20000
    (QCheck.make ~print:(fun ((n, a, b), axis) -> Printf.sprintf "plane %d axis %d at (%h, %h)" n axis a b) gen)
    (fun ((n, a, b), axis) ->
      let at v = match axis with 0 -> (v, a, b) | 1 -> (a, v, b) | _ -> (a, b, v) in
      let lo = at (Float.pred (float_of_int n)) and hi = at (Float.succ (float_of_int n)) in
      let m1 = Vec3.m () and m2 = Vec3.m () in
      let ok g =
        let x1, y1, z1 = lo and x2, y2, z2 = hi in
        Float.abs (Noise.noise g x1 y1 z1 -. Noise.noise g x2 y2 z2) < 1e-9
      in
      let x1, y1, z1 = lo and x2, y2, z2 = hi in
      Noise.dnoise x1 y1 z1 m1;
      Noise.dnoise x2 y2 z2 m2;
      (ok 1 && ok 2 && ok 3
       && Float.abs (m1.mx -. m2.mx) < 1e-9
       && Float.abs (m1.my -. m2.my) < 1e-9
       && Float.abs (m1.mz -. m2.mz) < 1e-9)
      || QCheck.Test.fail_report "a jump across the plane")

(* A media's densities multiply; where the product is already 0 the
   densities after it are not evaluated (a function pattern counting its
   calls), and elsewhere the product is the one taken by hand *)
let densities =
  Alcotest.test_case "Media.density_into: the product, later densities skipped where it is 0" `Quick (fun () ->
      let v x y z = Vec3.make x y z in
      let solid r g b = Pigment.solid (Color.rgbft r g b 0. 0.) in
      let map pattern entries = Pigment.Map { pattern; entries; xform = Transform.identity } in
      (* black up to x = 0.5, then to <1, 2, 3> at x = 1; or green only *)
      let first = map (Pattern.make (Pattern.Gradient (v 1. 0. 0.))) [| (0., solid 0. 0. 0.); (0.5, solid 0. 0. 0.); (1., solid 1. 2. 3.) |] in
      let green = solid 0. 1. 0. in
      let calls = ref 0 in
      let counted =
        Pattern.make
          (Pattern.Function
             (Pattern.fn ~slots:4 ~result:3 (fun s ->
                  incr calls;
                  s.(3) <- 0.25 +. (0.5 *. Float.abs (Float.sin (s.(1) +. s.(2)))))))
      in
      let second = map counted [| (0., solid 0.2 0.4 0.8); (1., solid 1. 1. 0.5) |] in
      let pig = Pigment.out () and out = Color.acc 0. and q = Vec3.m () in
      let at ds x y z =
        Vec3.set q x y z;
        Media.density_into { Media.default with density = ds } q pig out;
        (out.ar, out.ag, out.ab)
      in
      let by_hand ds x y z =
        Vec3.set q x y z;
        List.fold_left
          (fun (r, g, b) d ->
            Pigment.into d q pig;
            (r *. pig.r, g *. pig.g, b *. pig.b))
          (1., 1., 1.) ds
      in
      let same msg (a, b, c) (d, e, f) =
        if not (Float.equal a d && Float.equal b e && Float.equal c f) then
          Alcotest.failf "%s: %h %h %h, want %h %h %h" msg a b c d e f
      in
      for i = 0 to 99 do
        let x = float_of_int i /. 100. and y = float_of_int (i * 7 mod 13) and z = 0.3 in
        calls := 0;
        let want = by_hand [ first; second ] x y z in
        let hand_calls = !calls in
        calls := 0;
        same (Printf.sprintf "x = %g" x) want (at [ first; second ] x y z);
        if x <= 0.5 then begin
          same "zero" (0., 0., 0.) want;
          if !calls <> 0 then Alcotest.failf "x = %g: the density after a zero evaluated %d times" x !calls
        end
        else if !calls <> hand_calls || !calls = 0 then Alcotest.failf "x = %g: %d calls, %d by hand" x !calls hand_calls;
        (* one channel left: the rest is evaluated *)
        calls := 0;
        same "green" (by_hand [ green; second ] x y z) (at [ green; second ] x y z);
        if !calls = 0 then Alcotest.fail "a density after green skipped"
      done)

(* POV-Ray 3.7's noise against POV-Ray itself: the files in noise_pov/
   were written by POV-Ray 3.7 running the .pov files beside them
   (points to 17 decimals, then the value): f_noise3d for each
   generator (1, 2, 3: 40 lattice points and 360 random ones in
   [-20, 20]^3), and pattern functions of gradient x, y, z under a
   turbulence warp of amplitude 0.001 (one octave: DNoise; six with omega
   0.6 and lambda 2.3: DTurbulence) *)
let pov_dir = Helpers.data_dir "noise_pov"

let read_rows = Helpers.read_rows pov_dir

let pov_noise gen =
  Alcotest.test_case (Printf.sprintf "Noise.noise %d: POV-Ray's f_noise3d at 400 points" gen) `Quick (fun () ->
      let rows = read_rows (Printf.sprintf "n%d.txt" gen) in
      if List.length rows <> 400 then Alcotest.failf "%d rows" (List.length rows);
      List.iter
        (function
          | [ x; y; z; v ] ->
              let got = Noise.noise gen x y z in
              (* POV-Ray prints 17 decimals *)
              if Float.abs (got -. v) > 2e-16 then Alcotest.failf "(%.17g, %.17g, %.17g): %.17g, POV-Ray %.17g" x y z got v
          | _ -> Alcotest.fail "bad row")
        rows)

(* POV-Ray keeps a turbulence's omega and lambda in single precision *)
let single = Floats.single

let pov_dnoise =
  Alcotest.test_case "Noise.dnoise, dturbulence: POV-Ray's turbulence warp at 300 points" `Quick (fun () ->
      let rows = read_rows "dt.txt" in
      if List.length rows <> 300 then Alcotest.failf "%d rows" (List.length rows);
      let p = Vec3.m () and o = Vec3.m () in
      let frac v = v -. Float.floor v in
      let check what x y z vx vy vz =
        let near a b = Float.abs (a -. b) < 1e-15 in
        if not (near (frac (x +. (0.001 *. o.mx))) vx && near (frac (y +. (0.001 *. o.my))) vy && near (frac (z +. (0.001 *. o.mz))) vz)
        then Alcotest.failf "%s at (%.17g, %.17g, %.17g): %.17g %.17g %.17g, POV-Ray's pattern %.17g %.17g %.17g" what x y z
            (frac (x +. (0.001 *. o.mx))) (frac (y +. (0.001 *. o.my))) (frac (z +. (0.001 *. o.mz))) vx vy vz
      in
      List.iter
        (function
          | [ x; y; z; x1; y1; z1; x6; y6; z6 ] ->
              Noise.dnoise x y z o;
              check "dnoise" x y z x1 y1 z1;
              Vec3.set p x y z;
              Noise.dturbulence ~octaves:6 ~omega:(single 0.6) ~lambda:(single 2.3) p o;
              check "dturbulence" x y z x6 y6 z6
          | _ -> Alcotest.fail "bad row")
        rows)

(* the tables' make-up: the hash a permutation of 0 .. 4095, doubled;
   the numbers in [-1, 1], each with its half beside it *)
let pov_tables =
  Alcotest.test_case "POV-Ray's noise tables: a doubled permutation, numbers in [-1, 1]" `Quick (fun () ->
      let seen = Array.make 4096 false in
      for i = 0 to 4095 do
        let h = Noise.hash_table.(i) in
        if seen.(h) then Alcotest.failf "%d twice" h;
        seen.(h) <- true;
        if Noise.hash_table.(i + 4096) <> h then Alcotest.failf "entry %d not doubled" i
      done;
      for i = 0 to 266 do
        let v = Float.Array.get Noise.r_table (2 * i) in
        if v < -1. || v > 1. then Alcotest.failf "entry %d: %g" i v;
        if Float.Array.get Noise.r_table ((2 * i) + 1) <> v *. 0.5 then Alcotest.failf "entry %d: half" i
      done)

(* POV-Ray 3.7's noise patterns against POV-Ray itself: patterns.txt was
   written by POV-Ray 3.7 running patterns.pov beside it (300 random
   points in [-20, 20]^3 to 17 decimals, then the value of each of its 47
   pattern functions there: bozo, spotted, bumps, dents, granite,
   wrinkles in each generator, agate (agate_turb, octaves without
   turbulence), marble, wood, the spirals and bozo with classic
   turbulence, marble and bozo under a turbulence warp, crackle's forms,
   metrics, offsets and solid, black holes: repeated with turbulence
   (repeat widened, centre raised to the radius), plain with strength,
   falloff and inverse; octaves out of 1 to 10, kept within them; the
   waves (frequency, phase, poly_wave's exponent in single precision,
   sine, scallop and cubic as POV-Ray writes them)). The
   same functions, declared in camlray's language from that file's
   lines, are evaluated at the same points (one sphere's centre each) *)
let pov_patterns =
  Alcotest.test_case "noise patterns: POV-Ray's pattern functions at 300 points" `Quick (fun () ->
      let text = In_channel.with_open_text (Filename.concat pov_dir "patterns.pov") In_channel.input_all in
      let decls =
        List.filter (fun l -> String.length l > 10 && String.sub l 0 10 = "#declare F") (String.split_on_char '\n' text)
      in
      let n = List.length decls in
      if n <> 47 then Alcotest.failf "%d functions in patterns.pov" n;
      let rows = read_rows "patterns.txt" in
      if List.length rows <> 300 then Alcotest.failf "%d rows" (List.length rows);
      let b = Buffer.create 400_000 in
      List.iter (fun d -> Buffer.add_string b d; Buffer.add_char b '\n') decls;
      List.iter
        (function
          | x :: y :: z :: _ ->
              for k = 0 to n - 1 do
                Printf.bprintf b "sphere { <F%d(%.17g, %.17g, %.17g), 0, 0>, 1 }\n" k x y z
              done
          | _ -> Alcotest.fail "bad row")
        rows;
      let got = Array.of_list (List.map (fun ((c : Camlray.Vec3.t), _) -> c.x) (Scn.spheres (Scn.parse (Buffer.contents b)))) in
      let names = Array.of_list (List.map (fun d -> String.sub d 9 (String.length d - 9)) decls) in
      let bad = ref 0 and worst = Array.make n 0. in
      List.iteri
        (fun i row ->
          match row with
          | x :: y :: z :: vs ->
              List.iteri
                (fun k v ->
                  let g = got.((i * n) + k) in
                  let e = Float.abs (g -. v) in
                  if e > worst.(k) then worst.(k) <- e;
                  (* POV-Ray prints 17 decimals (the solid noise,
                     generator 3, is exact since its gradients are made
                     as POV-Ray makes them) *)
                  let tol = 1e-15 in
                  if e > tol then begin
                    incr bad;
                    if !bad <= 10 then
                      Printf.printf "%s at (%.17g, %.17g, %.17g): %.17g, POV-Ray %.17g\n" names.(k) x y z g v
                  end)
                vs
          | _ -> ())
        rows;
      Array.iteri (fun k w -> if w > 0. then Printf.printf "worst %g: %s\n" w names.(k)) worst;
      if !bad > 0 then Alcotest.failf "%d values differ from POV-Ray's" !bad)

let tests =
  ( "noise",
    List.map QCheck_alcotest.to_alcotest [ range_prop; continuity_prop ]
    @ [ densities; pov_noise 1; pov_noise 2; pov_noise 3; pov_dnoise; pov_tables; pov_patterns ] )
