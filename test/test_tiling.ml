(* POV-Ray 3.7's tiling pattern (lib/tiling.ml): values against POV-Ray's
   own, known answers of the layouts, the range, the periods and
   symmetries, the scene language. *)
open Camlray

(* POV-Ray 3.7.0's values of pigment { tiling N color_map { [0 rgb 0] [1
   rgb 1] } } at points (x, z) drawn at random in [-12, 12]^2 (y = 0.3),
   written by #write of the pigment function's red (POV-Ray's colours
   are single precision: 7 digits): for each N one point in each band
   (kind of tile), then two more. *)
let pov_values =
  [
    ( 1,
      [ (11.181025011274272, 3.2760967927230755, 0.6379500);
        (-0.8024715717887672, -6.0223145079850955, 0.9553710);
        (8.731657968073073, -1.590434681063154, 0.4633159) ] );
    ( 2,
      [ (2.8786934686076577, 9.419839962716177, 0.6827594);
        (-6.673809728276407, 10.029417547869826, 0.5357034);
        (-9.315132814765708, -6.725772929081175, 0.8017403) ] );
    ( 3,
      [ (9.015201670354045, 0.9826818418183088, 0.2979451);
        (-7.504266555305633, 9.891222640381013, 0.6903498);
        (9.752296076564189, -2.9128155817540393, 0.8941282);
        (-8.062193914331075, -0.12951984166389297, 0.4811234) ] );
    ( 4,
      [ (-7.743343825392273, -8.349377413361655, 0.8456571);
        (-11.36424549654225, 6.543116244148257, 0.7161692);
        (-4.686172561879776, -7.5333985806287735, 0.3976388) ] );
    ( 5,
      [ (-11.684885959998912, 0.4522402855689256, 0.2973247);
        (-11.875655908108609, 2.905642142264555, 0.5346116);
        (-11.0494559032492, 4.992947312303107, 0.8888157);
        (-0.2555305297150112, -2.1681711259689576, 0.3308424);
        (-6.331527157298178, 11.448248606046718, 0.6274511) ] );
    ( 6,
      [ (6.935940165756257, 5.244262496299172, 0.2557375);
        (9.917181143052222, -1.556369441923771, 0.9171811);
        (1.0972657606697807, -5.510598391646193, 0.9027342);
        (-3.686271147729427, -3.227529357938918, 0.6862711) ] );
    ( 7,
      [ (3.6657956614312237, -3.1296601777732516, 0.3791050);
        (-8.892201001963626, 10.369816705204968, 0.8377253);
        (-1.4113851984523662, -6.93529430100119, 0.7957216);
        (-4.613135473945443, 7.310250989000836, 0.5000000) ] );
    ( 8,
      [ (-0.5230188752810978, 1.6507759070142116, 0.2320779);
        (5.0243308621049705, 1.3691763704105213, 0.4778534);
        (-8.677005752147409, -11.066442573225695, 0.8502240);
        (9.312286538377471, -9.373913855611793, 0.6161060);
        (0.22363392920783465, -11.362852765098879, 0.5392772) ] );
    ( 9,
      [ (-4.4690237251271085, -3.0442304907003956, 0.1067223);
        (-9.250215466425338, 10.075498625188018, 0.5993593);
        (-0.8132783595503494, 4.485041597971004, 0.7761616);
        (-6.921080129901198, 7.746323457859997, 0.6666667);
        (6.294451021192236, -11.531392520184488, 0.9521036) ] );
    ( 10,
      [ (-2.1176206670044038, -6.289017648037761, 0.4219647);
        (4.742167838090604, 1.9975725240068458, 0.9951450);
        (-4.417394833736447, 4.50594370637693, 0.1652103) ] );
    ( 11,
      [ (4.83448857833503, -10.480812867749671, 0.2229924);
        (10.822708988288117, 0.2844845625302961, 0.4770103);
        (-8.620808980572226, 6.423951240820798, 0.7472060);
        (-3.2604273723579076, 7.659172049644211, 0.8263817);
        (8.927428682550655, -0.7903088547266801, 0.9516191) ] );
    ( 12,
      [ (7.624703881243408, 10.362355280286248, 0.0917631);
        (0.9297050677541892, -9.175827455980663, 0.5494484);
        (-5.7652454324451385, 7.8991315206277966, 0.9327543);
        (5.409106653511782, 8.50190273218367, 0.3346018);
        (1.7985489549577593, -8.708940350615638, 0.5323660) ] );
    ( 13,
      [ (3.734821539310465, -6.772936613013254, 0.1454432);
        (6.313968360962805, 0.07065141668325658, 0.6000559);
        (5.291274149271492, 3.582259395993842, 0.7411652);
        (-2.4740263760262224, -4.728805262765103, 0.6674656);
        (3.9078852981114487, -7.505890739035302, 0.0766217) ] );
    ( 14,
      [ (-0.2453323798825342, 7.702983709914373, 0.0612190);
        (-10.716565422414934, -2.0763449068358977, 0.3380243);
        (4.494030993546831, -2.2433402236186293, 0.5309751);
        (-6.034181165051224, -8.682565015899614, 0.7279827);
        (3.840174574367744, -6.775108062376992, 0.8276694);
        (-11.333846445971599, 8.644165857845024, 0.1886083);
        (-7.196003871782684, -3.9628537408921063, 0.8000002) ] );
    ( 15,
      [ (6.254820544797654, 3.2355588467874457, 0.2644412);
        (10.988302180307986, 7.901833935617897, 0.9018340);
        (8.199430328840258, 7.122918459382587, 0.8770816);
        (-5.877079623257061, 1.6964476010055396, 0.6964476) ] );
    ( 16,
      [ (1.7445408547633647, 2.590177347555332, 0.1930551);
        (-2.280217630388266, -5.494138323118476, 0.5349197);
        (9.200427302438866, -0.19701196537283483, 0.8500706);
        (-2.2612851462935293, 2.2330659940450133, 0.0000000);
        (3.853074513341551, -0.42275190642633254, 0.6666667) ] );
    ( 17,
      [ (10.374579889321371, 7.86932894863871, 0.1410018);
        (-4.769688235775028, -8.012617689560312, 0.2991703);
        (11.530590796733877, 8.806639730186816, 0.4316632);
        (-11.803550519003428, -8.190052376172984, 0.5717262);
        (3.131473004615742, -9.947866318269602, 0.8052119);
        (1.5046510094554737, 5.998361235949761, 0.9802202);
        (-2.6144632638000105, -10.018582781315452, 0.4924663);
        (0.9237403713454828, 8.711499563583986, 0.9911394) ] );
    ( 18,
      [ (-7.709598260864056, -1.071421693328634, 0.4285783);
        (-6.255279264006597, -3.3110661207025562, 0.7447208);
        (11.001638302347073, 6.945910556927768, 0.9983617);
        (10.413934846970704, 1.7667813687042297, 0.2667814) ] );
    ( 19,
      [ (-9.302313710866104, 11.450119212141754, 0.2463765);
        (-2.1381672821329367, 9.224107357958356, 0.4792931);
        (-8.150592225638821, -7.015422356085717, 0.8997638);
        (10.881739804260839, 6.080257101468802, 0.3124572);
        (3.8872661180531747, 8.915601353374218, 0.6319757) ] );
    ( 20,
      [ (7.113611143807325, 9.882075938834362, 0.1523637);
        (-4.283172613075742, -3.5337318925964016, 0.5862646);
        (3.233849055886699, -10.356754084666434, 0.9589495);
        (6.980641291239449, 3.4976616407506302, 0.6666495);
        (2.8991944973587964, 3.640463510444497, 0.6656496) ] );
    ( 21,
      [ (-11.737248681424477, 6.945066186353812, 0.1349225);
        (-8.359026129441109, 6.768666072461909, 0.2978489);
        (9.435538110657488, 6.658910381295463, 0.4268845);
        (8.333889712657287, 1.4740548221101184, 0.6042958);
        (-10.58760641109841, 6.2533047781915645, 0.7465207);
        (-11.56101490919502, 11.960994355371454, 0.8717223);
        (-5.49070970562536, -7.792030596125878, 0.4846378);
        (11.933004559933442, -1.4754182057165117, 0.4089728) ] );
    ( 22,
      [ (5.6815975871127105, -2.4137497689606966, 0.1006259);
        (5.406355064689731, -6.576605886820845, 0.5367579);
        (-1.6456779999764817, -7.257260155691127, 0.8217223);
        (1.0611220665884016, 9.465306624180009, 0.6666667);
        (10.446948570769035, 4.570304663984641, 0.6666667) ] );
    ( 23,
      [ (1.6372654022735684, -2.6876813393756, 0.1915227);
        (5.82730145049917, -3.3830433672720206, 0.3810742);
        (8.619488177033952, -4.804460779019738, 0.8542513);
        (5.178898196941916, 2.79001793423435, 0.6312316);
        (-5.768465178499106, 9.086062184787835, 0.4869376) ] );
    ( 24,
      [ (6.346295517484261, -2.4885674413499816, 0.1627110);
        (2.0614273096577787, -1.2676253722206754, 0.3218392);
        (0.9710847467582413, 9.032119865769548, 0.5040050);
        (10.749284343502783, -3.4831825903344855, 0.6440312);
        (1.647519833791888, -10.017594834328069, 0.9153910);
        (-3.049493627401417, -2.890874575565307, 0.1221149);
        (-6.8507146674326425, -0.242634854335952, 0.0000000) ] );
    ( 25,
      [ (9.252399717749189, -10.471785792725111, 0.1415140);
        (-5.233880536918035, 5.805093637156555, 0.2545902);
        (-11.493172041953814, -7.500811339239779, 0.4285610);
        (-4.3837969248145345, -4.146895904128183, 0.6139626);
        (-8.949888176505894, 8.982137548965898, 0.7819728);
        (4.439506702227403, -8.903923903802394, 0.9180836);
        (5.604785032944006, 10.19544129031604, 0.1714631);
        (6.211835843094585, 4.51677510340623, 0.1666677) ] );
    ( 26,
      [ (-8.691743093703813, 5.042130878437806, 0.3246053);
        (3.4132144859557068, 11.463272128129208, 0.6402537);
        (8.15710485823385, 4.764854056938749, 0.9748490);
        (-9.13275848262309, 1.2662096408349948, 0.3923006) ] );
    ( 27,
      [ (-2.8625128806714226, -7.9255674676796355, 0.4365751);
        (8.954761565885217, 1.8540890267710415, 0.8612654);
        (2.963126759734733, 1.8831501914847522, 0.0648544);
        (5.581801519166166, 5.563401213279785, 0.9928301) ] );
  ]

(* the same at points more than 120 from the origin (deeper in the
   Penrose tilings' deflation) *)
let pov_far =
  [
    (25, 178.64027535045528, 10.460079417205437, 0.1021532);
    (25, 133.79322819732903, 70.2001290093642, 0.8141554);
    (25, 67.44102674243994, 171.60415350729696, 0.6486761);
    (26, 158.23069036897058, -81.29955331825175, 0.9960077);
    (26, -131.37129767131324, -18.209045989953232, 0.2751780);
    (26, -134.31034403254984, -174.1826818264515, 0.2910149);
    (27, 147.90631745660357, -59.689106852675124, 0.7355253);
    (27, -160.8671937046729, -3.653931106360142, 0.3368091);
    (27, 75.80686087622466, 141.2277210366977, 0.3120166);
  ]

let point x y z =
  let p = Vec3.m () in
  Vec3.set p x y z;
  p

let value n x z =
  let r = { Tiling.v = nan } in
  Tiling.eval n (point x 0.3 z) r;
  r.v

let pov_agrees () =
  List.iter
    (fun (n, pts) ->
      List.iter
        (fun (x, z, expected) ->
          let what = Printf.sprintf "tiling %d at (%g, %g)" n x z in
          Scn.close ~eps:1e-6 what expected (value n x z);
          (* through the pattern (ramp wave, frequency 1) *)
          Scn.close ~eps:1e-6 (what ^ ", as a pattern") expected
            (Pattern.value (Pattern.make (Pattern.Tiling n)) (Vec3.make x (-2.) z)))
        pts)
    pov_values;
  List.iter
    (fun (n, x, z, expected) -> Scn.close ~eps:1e-6 (Printf.sprintf "tiling %d at (%g, %g)" n x z) expected (value n x z))
    pov_far

(* every band is hit by some of POV-Ray's points, and no band above *)
let bands () =
  Alcotest.(check int) "27 tilings" 27 Tiling.count;
  List.iter
    (fun (n, pts) ->
      let k = Tiling.bands n in
      let seen = Array.make k false in
      List.iter
        (fun (x, z, _) ->
          let b = int_of_float (value n x z *. float_of_int k) in
          if b >= k then Alcotest.failf "tiling %d: band %d of %d" n b k;
          seen.(b) <- true)
        pts;
      Array.iteri (fun b s -> if not s then Alcotest.failf "tiling %d: band %d of %d not met" n b k) seen)
    pov_values

(* known answers worked out from the layouts *)
let layouts () =
  let c = Scn.close ~eps:1e-12 in
  (* 1: unit squares; 0 at the centre, 1 on the sides, the max norm *)
  c "square centre" 0. (value 1 0.5 0.5);
  c "square centre, negative" 0. (value 1 (-2.5) (-7.5));
  c "square side" 1. (value 1 0. 0.3);
  c "square, a quarter in" 0.5 (value 1 0.25 0.6);
  (* 10: the rows z in [1, 2) shifted by half a square *)
  c "offset square centre" 0. (value 10 0. 1.5);
  c "offset row's side" 1. (value 10 0.5 1.5);
  c "unshifted row" 0. (value 10 0.5 0.5);
  (* 6: a 2 x 1 rectangle along z (band 1) over the cells (0, 0) and (0,
     1); one along x (band 0) centred at (2, 0.5) *)
  c "rectangle along z, centre" 0.5 (value 6 0.5 1.);
  c "rectangle along z, its long side" 1. (value 6 0. 1.);
  c "rectangle along z, inside its core" 0.5 (value 6 0.5 0.75);
  c "rectangle along x, centre" 0. (value 6 2. 0.5);
  (* 15: unit squares in [0, 0.5], 2 x 2 squares from 0.50000001 *)
  c "small square centre" 0. (value 15 0.5 0.5);
  c "small square side" 0.5 (value 15 0.5 0.);
  c "large square side" 1.00000001 (value 15 1. 0.5);
  c "large square centre" 0.50000001 (value 15 2. 0.);
  c "large square core" 0.50000001 (value 15 2.4 (-0.3));
  (* 11: the unit square at (1.5, 1.5) (band 0), rectangles along x (band
     1) and along z (band 2) around it *)
  c "square_rectangle: square centre" 0. (value 11 1.5 1.5);
  c "square_rectangle: along x" (1. /. 3.) (value 11 2. 0.5);
  c "square_rectangle: along z" (2. /. 3.) (value 11 0.5 1.);
  (* 7: the square between four octagons at the centre of each period
     (1 + sqrt2), an octagon around each corner of the period *)
  let period = 1. +. Float.sqrt 2. in
  c "octagon_square: square centre" 0. (value 7 (period /. 2.) (period /. 2.));
  c "octagon_square: octagon centre (the bottom of its band)" 0.5 (value 7 0. 0.);
  c "octagon_square: an octagon's side" 1. (value 7 0. (period /. 2.));
  (* the Penrose tilings are 1 at the origin *)
  List.iter (fun n -> c (Printf.sprintf "tiling %d at the origin" n) 1. (value n 0. 0.)) [ 25; 26; 27 ]

(* lattice vectors of the periodic tilings 1 to 24 *)
let periods =
  let s2 = Float.sqrt 2. and s3 = Float.sqrt 3. in
  let sq p = [ (p, 0.); (0., p) ] in
  [| sq 1.; [ (3., 0.); (0., s3) ]; [ (1., 0.); (0., s3) ]; [ (1., 0.); (0., s3) ]; [ (3., 0.); (0., s3) ]; sq 4.;
     sq (1. +. s2); [ (1., 0.); (0., 2. +. s3) ]; [ (2., 0.); (0., 2. *. s3) ]; [ (1., 0.); (0., 2.) ]; sq 3.; sq 6.;
     sq (4. /. s2); sq (4. /. s2); sq 5.; [ (3. +. s3, 0.); (0., 2. *. (1. +. s3)) ];
     [ (3. +. s3, 0.); (0., 2. *. (1. +. s3)) ]; sq 4.;
     (* 19 and 20: each row of height 3 sqrt3 / 2 shifted by half a unit *)
     [ (7., 0.); (-0.5, 1.5 *. s3) ]; [ (7., 0.); (0.5, 1.5 *. s3) ]; sq (1. +. s3);
     [ (2. +. s3, 0.); (0., 3. +. (2. *. s3)) ]; [ (3. +. s3, 0.); (0., 3. +. (3. *. s3)) ];
     [ (3. +. s3, 0.); (0., 3. +. (3. *. s3)) ] |]

let props =
  let open QCheck in
  let coord = Gen.float_range (-300.) 300. in
  let gen = Gen.(triple (int_range 1 27) coord coord) in
  let print (n, x, z) = Printf.sprintf "tiling %d at (%h, %h)" n x z in
  [
    Test.make ~name:"tiling values in [0, 1] (15: POV-Ray's 1.00000001), y ignored" ~count:20000 (make ~print gen)
      (fun (n, x, z) ->
        let v = value n x z in
        let r = { Tiling.v = nan } in
        Tiling.eval n (point x (-41.7) z) r;
        ((v >= 0. && v <= (if n = 15 then 1.00000001 else 1.)) || Test.fail_reportf "value %h" v)
        && Int64.equal (Int64.bits_of_float v) (Int64.bits_of_float r.v) || Test.fail_reportf "y changes %h to %h" v r.v);
    Test.make ~name:"tilings 1 to 24 repeat along their lattice vectors" ~count:20000
      (make ~print Gen.(triple (int_range 1 24) coord coord))
      (fun (n, x, z) ->
        let v = value n x z in
        List.for_all
          (fun (dx, dz) ->
            let w = value n (x +. dx) (z +. dz) in
            Float.abs (v -. w) < 1e-9 || Test.fail_reportf "%h moved by (%g, %g): %h" v dx dz w)
          periods.(n - 1));
    Test.make ~name:"Penrose tilings: mirror about x (exact), five-fold turn" ~count:5000
      (make ~print Gen.(triple (int_range 25 27) (float_range (-60.) 60.) (float_range (-60.) 60.)))
      (fun (n, x, z) ->
        let v = value n x z in
        let a = 2. *. Float.pi /. 5. in
        let tx = (x *. Float.cos a) -. (z *. Float.sin a) and tz = (x *. Float.sin a) +. (z *. Float.cos a) in
        (Int64.equal (Int64.bits_of_float v) (Int64.bits_of_float (value n x (-.z)))
        || Test.fail_reportf "mirrored: %h" (value n x (-.z)))
        && Float.abs (v -. value n tx tz) < 1e-6 || Test.fail_reportf "turned: %h, %h" v (value n tx tz));
  ]

let allocation () =
  for n = 1 to 27 do
    let p = Pattern.make (Pattern.Tiling n) in
    let words = Test_pattern.words_over_1000 ~step:0.0137 ~y:0.2 ~z:(-3.7) p in
    if words > 0. then Alcotest.failf "tiling %d: %.0f minor words over 1000 evaluations" n words
  done

(* the scene language: a plane seen from above, ambient only *)
let scene () =
  let top ?(at = (0.5, 0.5)) pigment =
    let x, z = at in
    Scn.pixel
      (Printf.sprintf
         "camera { location <%g, 5, %g> look_at <%g, 0, %g> sky z angle 1 }\n\
          plane { y, 0 pigment { %s } finish { ambient 1 diffuse 0 } }" x z x z pigment)
  in
  let map = "color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] }" in
  Scn.color "tiling 1, a square's centre" (1., 0., 0.) (top ("tiling 1 " ^ map));
  Scn.color "tiling 1 scaled, halfway to the side" (0., 1., 0.) (top ~at:(0.5, 1.) ("tiling 1 scale 2 " ^ map));
  Scn.color "tiling 15, a large square's core" (0., 1., 0.) (top ~at:(2.3, 0.2) ("tiling 15 " ^ map));
  (* POV-Ray 3.7.0 truncates the number, then wants 1 to 27 (measured:
     27.9 and 1.5 draw 27 and 1; 0.5, -0.5 and 28 are errors) *)
  let kind src =
    match (Scn.compile (Printf.sprintf "sphere { 0, 1 pigment { %s } }" src)).objects.(0).texture with
    | { pigment = Pigment.Map { pattern; _ }; _ } :: _ -> pattern.kind
    | _ -> Alcotest.failf "no pattern in %s" src
  in
  if kind "tiling 27.9" <> Pattern.Tiling 27 then Alcotest.fail "tiling 27.9 is tiling 27";
  if kind "tiling 1.5" <> Pattern.Tiling 1 then Alcotest.fail "tiling 1.5 is tiling 1";
  if kind "tiling 3 frequency 2" <> Pattern.Tiling 3 then Alcotest.fail "tiling 3";
  ignore (Scn.compile "sphere { 0, 1 normal { tiling 16 0.5 scale 0.2 } }");
  ignore (Scn.compile "sphere { 0, 1 texture { tiling 2 texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }");
  Scn.check_message "sphere { 0, 1 pigment { tiling 0 } }" "tiling takes a number from 1 to 27, found 0";
  Scn.check_message "sphere { 0, 1 pigment { tiling 28 } }" "tiling takes a number from 1 to 27, found 28";
  Scn.check_message "sphere { 0, 1 pigment { tiling 0.5 } }" "tiling takes a number from 1 to 27, found 0.5";
  Scn.check_message "sphere { 0, 1 pigment { tiling -0.5 } }" "tiling takes a number from 1 to 27, found -0.5";
  (* pavement (POV-Ray's tables of polyform tilings) is refused, located *)
  let d = Scn.error "plane { y, 0 pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2 } }" in
  if not (Scn.contains d.Camlray_lang.Diag.msg "pavement is not supported by camlray") then
    Alcotest.failf "pavement: %s" d.msg;
  Alcotest.(check (pair int int)) "pavement's line and column" (1, 24)
    (Camlray_lang.Loc.line d.loc, Camlray_lang.Loc.col d.loc);
  (* POV-Ray 3.7.0 refuses a tiling in a pattern function; camlray takes it *)
  Scn.close ~eps:1e-12 "function { pattern { tiling 1 } }" 0.5
    (Scn.float ~prelude:"#declare F = function { pattern { tiling 1 } }" "F(0.25, 0, 0.5)");
  Scn.check_message "sphere { 0, 1 pigment { tiling } }" "expected"

let tests =
  ( "tiling",
    [
      Alcotest.test_case "values = POV-Ray's" `Quick pov_agrees;
      Alcotest.test_case "bands" `Quick bands;
      Alcotest.test_case "layouts: known answers" `Quick layouts;
      Alcotest.test_case "allocation-free" `Quick allocation;
      Alcotest.test_case "scene language" `Quick scene;
    ]
    @ List.map QCheck_alcotest.to_alcotest props )
