(* POV-Ray 3.7's tiling pattern: 27 tilings of the xz plane. Each tiling
   has k kinds of tile; kind i takes the band [i/k, (i+1)/k] of the
   value, which grows from the inside of the tile towards its border (a
   thin band at the top of each band of a colour map draws the grout).
   The layouts, scales and bands are POV-Ray's (its pattern.cpp, read
   for its facts); camlray's own code.

   Every tiling takes its point from a [Vec3.m] and leaves its value in
   a [result]: a float passed to or returned from a function that is not
   inlined would be boxed. The helpers marked [@inline] return floats
   into their callers' code. *)

type result = { mutable v : float }

let s3 = 1.7320508075688772935 (* sqrt 3 *)
let s3_2 = 0.86602540378443864676 (* sqrt 3 / 2 *)
let s2 = 1.4142135623730950488 (* sqrt 2 *)
let s2_2 = 0.70710678118654752440 (* sqrt 2 / 2 *)

let[@inline] mx (a : float) b = if a > b then a else b
let[@inline] mn (a : float) b = if a < b then a else b

(* [x] taken into [0, p) (POV-Ray's x - p floor(x / p)) *)
let[@inline] wrap x p = x -. (p *. Float.floor (x /. p))

(* 1: unit squares, corners on the integer grid; the distance from the
   centre in the max norm, 0 at the centre, 1 on the sides *)
let square (p : Vec3.m) (r : result) =
  let x = Float.abs p.mx and z = Float.abs p.mz in
  let x = 2. *. Float.abs (x -. Float.floor x -. 0.5) and z = 2. *. Float.abs (z -. Float.floor z -. 0.5) in
  r.v <- mx x z

(* The hexagon around the corner (1, sqrt3/2) of the strip [0, 1.5] x
   [0, sqrt3/2] that a hexagonal tiling folds into (side 1, flat sides
   facing +-z): 0 at its centre, 1 on its sides. *)
let[@inline] hex_in_strip x z =
  let x = ref x and z = ref z in
  if (s3 *. !x) +. !z < s3_2 then begin
    (* the corner of the neighbour below: mirrored onto this one *)
    x := 0.5 -. !x;
    z := s3_2 -. !z
  end;
  if !x > 1. then x := 2. -. !x;
  let across = 1. -. (!z /. s3_2) and slant = 1. -. (((s3 *. !x) +. !z -. s3_2) /. s3) in
  mx 0. (mn 1. (mx across slant))

(* 2: hexagons of side 1, centred on the origin, corners along x *)
let hexagon (p : Vec3.m) (r : result) =
  let x = wrap (p.mx +. 0.5) 3. and z = wrap p.mz s3 in
  let z = if z > s3_2 then s3 -. z else z in
  if x > 1.5 then r.v <- hex_in_strip (x -. 1.5) (s3_2 -. z) else r.v <- hex_in_strip x z

(* The equilateral triangles of side 1 (bases along x, every other one
   pointing down) folded into the half-triangle [0, 0.5] x [0, sqrt3/2]:
   [flip] (0 or 1) says which of the two orientations the point starts
   in; the result is the orientation the point is in (0 or 1) plus its
   distance from the triangle's centre, 0 there and 1 on its sides. A
   point on x = 0 is moved to the apex of the next triangle, which
   changes its orientation when [edge_flips]. *)
let[@inline] triangle_fold ~edge_flips x z flip =
  let x = ref (x -. Float.floor x) and z = ref (wrap z s3) and flip = ref flip in
  if !z > s3_2 then begin
    z := s3 -. !z;
    flip := 1 - !flip
  end;
  if !x > 0.5 then x := 1. -. !x;
  if !x <> 0. then begin
    if !z /. !x > s3 then begin
      z := s3_2 -. !z;
      x := 0.5 -. !x;
      flip := 1 - !flip
    end
  end
  else begin
    z := s3_2 -. !z;
    x := 0.5;
    if edge_flips then flip := 1 - !flip
  end;
  let base = 1. -. (!z *. 2. *. s3) and side = 1. -. (((s3 *. !x) -. !z) *. s3) in
  float_of_int !flip +. mx base side

(* 3: equilateral triangles of side 1, two bands (up, down) *)
let triangle (p : Vec3.m) (r : result) = r.v <- triangle_fold ~edge_flips:false p.mx p.mz 0 /. 2.

(* The lozenges of tilings 4 and 5 (two equilateral triangles of side
   1 joined along a side: rhombs of side 1, angles 60 and 120 degrees),
   for a point of the strip [0, 1.5] x [0, sqrt3/2] (one lozenge lying
   along x, folded onto a quarter of it): 0 inside, 1 on the sides. *)
let[@inline] lozenge_folded x z =
  let x = ref x and z = ref z in
  if 2. *. !z > s3_2 then begin
    z := s3_2 -. !z;
    x := 1.5 -. !x
  end;
  if !x > 0.75 then x := !x -. 1.;
  if !x <> 0. && !z /. !x > s3 then begin
    z := s3_2 -. !z;
    x := 0.5 -. !x
  end;
  let d1 = 1. -. (!z *. 4. *. s3 /. 3.) and d2 = 1. -. (Float.abs ((s3 *. !x) -. !z) *. s3 *. 2. /. 3.) in
  mx d1 d2

(* 4: lozenges, all the same way (one band) *)
let lozenge (p : Vec3.m) (r : result) =
  let x = p.mx -. Float.floor p.mx and z = wrap p.mz s3 in
  (* the upper half row: half a lozenge along *)
  if z > s3_2 then r.v <- lozenge_folded (x +. 0.5) (z -. s3_2) else r.v <- lozenge_folded x z

(* 5: the lozenges of three orientations around each vertex (a cube
   seen along its diagonal), one band each *)
let rhombus (p : Vec3.m) (r : result) =
  let x = ref (wrap (p.mx +. 0.5) 3.) and z = ref (wrap p.mz s3) and kind = ref 0 in
  if !z > s3_2 then begin
    z := s3 -. !z;
    kind := 2 - !kind
  end;
  if !x > 1.5 then begin
    x := !x -. 1.5;
    z := s3_2 -. !z;
    kind := 2 - !kind
  end;
  if !x < 0.5 then begin
    x := 1. -. !x;
    kind := 2 - !kind
  end;
  x := !x -. 0.5;
  if !x = 0. || !z /. !x > s3 then begin
    (* the upright lozenge turned by -60 degrees onto the others *)
    let x0 = !x and z0 = !z in
    x := (x0 /. 2.) +. (z0 *. s3_2);
    z := (z0 /. 2.) -. (x0 *. s3_2);
    kind := 1
  end;
  let v = (lozenge_folded !x !z /. 3.) +. (float_of_int !kind /. 3.) in
  r.v <- mx 0. (mn 1. v)

(* Tilings by axis-aligned rectangles on the integer grid with a period
   of [n] x [n] cells: each cell's tile (its centre, half sizes and band)
   found once from the list of the tiles of one period. The value: 1
   minus twice the distance to the tile's nearest side (at least 0), plus
   the band, times [scale]. *)
type boxes = { n : int; cx : float array; cz : float array; hx : float array; hz : float array; band : float array; scale : float }

let boxes n ~scale tiles =
  let cells = n * n in
  let b =
    { n; cx = Array.make cells nan; cz = Array.make cells 0.; hx = Array.make cells 0.; hz = Array.make cells 0.;
      band = Array.make cells 0.; scale }
  in
  let period = float_of_int n in
  List.iter
    (fun (cx, cz, hx, hz, band) ->
      for i = 0 to n - 1 do
        for k = 0 to n - 1 do
          let px = float_of_int i +. 0.5 and pz = float_of_int k +. 0.5 in
          (* the tile or one of its copies a period away *)
          for sx = -1 to 1 do
            for sz = -1 to 1 do
              let tx = cx +. (float_of_int sx *. period) and tz = cz +. (float_of_int sz *. period) in
              if Float.abs (px -. tx) < hx && Float.abs (pz -. tz) < hz then begin
                let c = i + (n * k) in
                if not (Float.is_nan b.cx.(c)) then invalid_arg "Tiling.boxes: tiles overlap";
                b.cx.(c) <- tx; b.cz.(c) <- tz; b.hx.(c) <- hx; b.hz.(c) <- hz; b.band.(c) <- band
              end
            done
          done
        done
      done)
    tiles;
  if Array.exists Float.is_nan b.cx then invalid_arg "Tiling.boxes: a cell has no tile";
  b

(* the value of tile [c] at (x, z) (coordinates of the period) *)
let[@inline] box_value b c x z =
  let ex = Array.unsafe_get b.hx c -. Float.abs (x -. Array.unsafe_get b.cx c)
  and ez = Array.unsafe_get b.hz c -. Float.abs (z -. Array.unsafe_get b.cz c) in
  (mx 0. (1. -. (2. *. mn ex ez)) +. Array.unsafe_get b.band c) *. b.scale

let[@inline] cell_of x n = Int.min (n - 1) (Int.max 0 (truncate x))

let boxes_value b (p : Vec3.m) (r : result) =
  let period = float_of_int b.n in
  let x = wrap p.mx period and z = wrap p.mz period in
  r.v <- box_value b (cell_of x b.n + (b.n * cell_of z b.n)) x z

(* a 2 x 1 rectangle centred at (cx, cz), long along x (band 0 unless
   given) or along z (band 1 unless given); a square of half side [half]
   (0.5 unless given) *)
let along_x ?(band = 0.) cx cz = (cx, cz, 1., 0.5, band)
let along_z ?(band = 1.) cx cz = (cx, cz, 0.5, 1., band)
let sq ?(half = 0.5) band cx cz = (cx, cz, half, half, band)

(* 6: 2 x 1 rectangles in a staircase, two bands (along x, along z) *)
let rectangles =
  boxes 4 ~scale:0.5
    [ along_z 0.5 1.; along_z 1.5 2.; along_z 2.5 3.; along_z 3.5 0.; along_x 2. 0.5; along_x 3. 1.5; along_x 0. 2.5;
      along_x 1. 3.5 ]

(* 7: regular octagons of side 1 on a square grid of period 1 + sqrt2,
   with squares of side 1 (turned by 45 degrees) between them: the
   squares take [0, 0.5), the octagons (0.5, 1] *)
let octagon_square (p : Vec3.m) (r : result) =
  let period = s2 +. 1. and half = s2_2 +. 0.5 in
  let a = Float.abs (wrap p.mx period -. half) and b = Float.abs (wrap p.mz period -. half) in
  let far = mx a b and near = mn a b in
  if far +. near < s2_2 then r.v <- (far +. near) /. s2
  else r.v <- mx 0.500000000001 (mx (1. -. near) ((s2 +. s2_2 -. (far +. near)) /. s2))

(* 8: rows of unit squares between rows of triangles (the elongated
   triangular tiling): triangles up and down, then squares *)
let square_triangle (p : Vec3.m) (r : result) =
  let x = ref (p.mx -. Float.floor p.mx) and z = ref (wrap p.mz (2. +. s3)) in
  (* the upper row of squares and triangles: half a square along *)
  if !z > s3_2 +. 1. then begin
    z := !z -. (s3_2 +. 1.);
    x := !x +. if !x > 0.5 then -0.5 else 0.5
  end;
  let x = if !x > 0.5 then 1. -. !x else !x in
  let z = !z -. 1. in
  if z > 0. then begin
    (* a triangle on top of the row of squares *)
    let x = ref x and z = ref z and flip = ref 0 in
    if !x <> 0. then begin
      if !z /. !x > s3 then begin
        z := s3_2 -. !z;
        x := 0.5 -. !x;
        flip := 1
      end
    end
    else begin
      z := s3_2 -. !z;
      x := 0.5;
      flip := 1
    end;
    let d1 = 1. -. (2. *. !z *. s3) and d2 = 1. -. (((s3 *. !x) -. !z) *. s3) in
    r.v <- (float_of_int !flip +. mx d1 d2) /. 3.
  end
  else begin
    let z = if z < -0.5 then -1. -. z else z in
    let dx = mn (2. +. (2. *. s3 *. Float.abs x)) 3. and dz = mn (2. +. (2. *. s3 *. Float.abs z)) 3. in
    r.v <- (5.0000001 -. mn dx dz) /. 3.
  end

(* the hexagon of the hexagon and triangle tilings, in the folded
   corner [0, 1] x [0, sqrt3/2] (centre at (1, sqrt3/2)), from 2 on its
   sides to 3 at its centre, at least [low] *)
let[@inline] hex_band x z low =
  let d1 = 2. +. (2. *. (z *. s3)) and d2 = 2. +. (2. *. ((s3 *. x) +. z -. s3_2) *. s3_2) in
  mx (5. -. mn d1 d2) low

(* 9: hexagons with triangles between them (the trihexagonal tiling):
   triangles up and down, then hexagons *)
let hexagon_triangle (p : Vec3.m) (r : result) =
  let x = ref (wrap (p.mx +. 0.5) 2.) and z = ref (wrap p.mz (2. *. s3)) in
  if !z > s3 then begin
    z := !z -. s3;
    x := !x +. if !x < 1. then 1. else -1.
  end;
  let flip = if !z > s3_2 then 1. else 0. in
  let z = if !z > s3_2 then s3 -. !z else !z in
  let x = if !x > 1. then 2. -. !x else !x in
  if (s3 *. x) +. z < s3_2 then begin
    let d1 = 1. -. (z *. 2. *. s3) and d2 = 1. +. (((s3 *. x) +. z -. s3_2) *. s3) in
    r.v <- (flip +. mx d1 d2) /. 3.
  end
  else r.v <- hex_band x z 2.0000001 /. 3.

(* 10: unit squares, every other row shifted by half a square *)
let square_offset (p : Vec3.m) (r : result) =
  let z = wrap p.mz 2. in
  let odd = z > 1. in
  let x = if odd then p.mx +. 0.5 else p.mx and z = if odd then z -. 1. else z in
  let x = x -. Float.floor x in
  r.v <- mx (2. *. Float.abs (x -. 0.5)) (2. *. Float.abs (z -. 0.5))

(* 11: a unit square with four 2 x 1 rectangles turning around it: the
   square, the rectangles along x, the rectangles along z *)
let square_rectangle_boxes =
  boxes 3 ~scale:(1. /. 3.) [ sq 0. 1.5 1.5; along_x ~band:1. 2. 0.5; along_x ~band:1. 1. 2.5; along_z ~band:2. 0.5 1.; along_z ~band:2. 2.5 2. ]

let square_rectangle (p : Vec3.m) (r : result) = boxes_value square_rectangle_boxes p r

(* 12: the same turned both ways around each square: the plane cut in
   6 x 6 blocks, each mirrored about its centre onto the pattern of 11.
   POV-Ray puts the points whose folded coordinate is 3 (the blocks'
   edges) on a rectangle of its own. *)
let rectangle_square (p : Vec3.m) (r : result) =
  let x = Float.abs (wrap p.mx 6. -. 3.) and z = Float.abs (wrap p.mz 6. -. 3.) in
  let b = square_rectangle_boxes in
  let i = truncate x and k = truncate z in
  if i > 2 || k > 2 then
    r.v <- (mx (2. *. Float.abs (x -. 0.5)) (2. *. (mx z 0.5 -. 0.5)) +. 2.) /. 3.
  else r.v <- box_value b (i + (3 * k)) x z

(* 13 and 14: squares of side sqrt2 on a grid of period 2 sqrt2, the
   gaps between them cut into hexagons pointed at both ends (the plane
   scaled by sqrt2 and cut in 4 x 4 blocks folded about their centre
   into [0, 2]^2, a square at the centre): 13, the squares (with a flat
   core), the hexagons along x, the hexagons along z; 14, the hexagons
   by their side of the square (bands 0 to 3), then the squares. *)
let[@inline] internal_fold c = wrap (c *. s2) 4. -. 2.

let square_internal (p : Vec3.m) (r : result) =
  let x = Float.abs (internal_fold p.mx) and z = Float.abs (internal_fold p.mz) in
  match truncate x + (2 * truncate z) with
  | 0 -> r.v <- mx (2. *. mx (x -. 0.5) 0.) (2. *. mx (z -. 0.5) 0.) /. 3.
  | 1 ->
      let a = (2. +. (Float.abs (1.5 -. x) *. 2.)) /. 3. in
      r.v <- (if z > 0.5 then mx a ((3. -. (s2 *. Float.abs (x -. z))) /. 3.) else a)
  | 2 ->
      let a = (1. +. (Float.abs (1.5 -. z) *. 2.)) /. 3. in
      r.v <- (if x > 0.5 then mx a ((2. -. (s2 *. Float.abs (x -. z))) /. 3.) else a)
  | 3 ->
      if x > z then r.v <- mx ((2. +. (Float.abs (1.5 -. x) *. 2.)) /. 3.) ((3. -. (s2 *. Float.abs (z -. x))) /. 3.)
      else r.v <- mx ((1. +. (Float.abs (1.5 -. z) *. 2.)) /. 3.) ((2. -. (s2 *. Float.abs (x -. z))) /. 3.)
  | _ -> r.v <- 0.

let square_internal_5 (p : Vec3.m) (r : result) =
  let x = internal_fold p.mx and z = internal_fold p.mz in
  (* the small squares' bands by the side of the block they are on *)
  let side_x = if x < 0. then 1. else 0. and side_z = if z < 0. then 2. else 3. in
  let x = Float.abs x and z = Float.abs z in
  match truncate x + (2 * truncate z) with
  | 0 -> r.v <- (4.000001 +. mx (2. *. mx (x -. 0.5) 0.) (2. *. mx (z -. 0.5) 0.)) /. 5.
  | 1 ->
      let a = Float.abs (1.5 -. x) *. 2. in
      let a = if z > 0.5 then mx a (1. -. (s2 *. Float.abs (x -. z))) else a in
      r.v <- (a +. side_x) /. 5.
  | 2 ->
      let a = Float.abs (1.5 -. z) *. 2. in
      let a = if x > 0.5 then mx a (1. -. (s2 *. Float.abs (x -. z))) else a in
      r.v <- (a +. side_z) /. 5.
  | 3 ->
      if x > z then r.v <- (mx (Float.abs (1.5 -. x) *. 2.) (1. -. (s2 *. Float.abs (z -. x))) +. side_x) /. 5.
      else r.v <- (mx (Float.abs (1.5 -. z) *. 2.) (1. -. (s2 *. Float.abs (x -. z))) +. side_z) /. 5.
  | _ -> r.v <- 0.

(* 15: unit squares and 2 x 2 squares *)
let square_double =
  boxes 5 ~scale:0.5
    [ sq 0. 0.5 0.5; sq 0. 2.5 1.5; sq 0. 4.5 2.5; sq 0. 1.5 3.5; sq 0. 3.5 4.5;
      (* POV-Ray's band of the large squares starts a hair above 0.5 *)
      sq ~half:1. 1.00000002 2. 0.; sq ~half:1. 1.00000002 4. 1.; sq ~half:1. 1.00000002 1. 2.;
      sq ~half:1. 1.00000002 3. 3.; sq ~half:1. 1.00000002 0. 4. ]

(* 16 and 17: hexagons, squares and triangles (the rhombitrihexagonal
   tiling, sides 1): three bands (triangles, squares, hexagons), or six
   (17: the squares by their three orientations, the triangles by their
   two, then the hexagons). The plane is folded into the corner [0, 1 +
   sqrt3/2]^2 with a hexagon's centre at its top right; its lower left
   part turned by 60 degrees about that corner's centre onto the rest. *)
let hexagon_square_triangle ~six (p : Vec3.m) (r : result) =
  let x = ref (wrap (p.mx +. 0.5) (3. +. s3)) and z = ref (wrap p.mz (2. *. (1. +. s3))) in
  let mir_x = ref 0 and mir_z = ref 0 and turned = ref 0 in
  if !x > s3_2 +. 1.5 then begin
    x := !x -. (s3_2 +. 1.5);
    z := !z +. (if !z < s3 +. 1. then s3_2 +. 0.5 else -1. *. (s3_2 +. 0.5))
  end;
  if !z > s3 +. 1. then z := !z -. (s3 +. 1.);
  if !z > 0.5 +. s3_2 then begin
    z := s3 +. 1. -. !z;
    mir_z := 1 - !mir_z
  end;
  if !x > 1. +. s3_2 then begin
    x := s3 +. 2. -. !x;
    mir_x := 1 - !mir_x
  end;
  if (s3 *. !x) +. !z < s3_2 +. 2. && !x < 0.5 +. s3_2 then begin
    let zc = !z -. (0.5 +. s3_2) and xc = !x -. (1. +. s3_2) in
    let xt = (xc /. 2.) -. (zc *. s3_2) and zt = (zc /. 2.) +. (xc *. s3_2) in
    z := zt +. (0.5 +. s3_2);
    x := xt +. (1. +. s3_2);
    turned := 1 - !turned;
    if !z < 0. then z := -1. *. !z;
    if !x > 1. +. s3_2 then begin
      x := s3 +. 2. -. !x;
      mir_x := 1 - !mir_x;
      mir_z := 1 - !mir_z
    end
  end;
  let x = !x and z = !z in
  if (not ((s3 *. x) +. z < s3_2 +. 2.)) && not (z < 0.5) then begin
    (* the hexagon *)
    let z = Float.abs (z -. 0.5) and x = Float.abs (x -. s3_2) in
    let d = mn (2. *. z *. s3) ((((s3 *. x) +. z) *. s3) -. 1.5) in
    if six then r.v <- mx (6. -. d) 5.000001 /. 6. else r.v <- mx (3. -. d) 2.0000001 /. 3.
  end
  else if z < 0.5 then begin
    if x > s3_2 +. 0.5 then begin
      (* a square *)
      let x = x -. (s3_2 +. 0.5) and z = z -. 0.5 in
      let d = mx (mx (1. +. (z *. 2. *. s3)) 0.) (mx (1. -. (x *. 2. *. s3)) 0.) in
      if six then
        r.v <- (d +. (float_of_int !turned *. (1.000001 +. float_of_int ((!mir_x + !mir_z) mod 2)))) /. 6.
      else r.v <- d /. 3.
    end
    else begin
      (* a triangle *)
      let x = Float.abs (x -. (s3_2 +. 0.5)) in
      let d = mx (2. -. (x *. 2. *. s3)) ((((s3 *. z) +. x) *. s3) +. 0.5) in
      if six then r.v <- ((if (!turned + !mir_x) mod 2 = 1 then 2. else 3.) +. d) /. 6. else r.v <- d /. 3.
    end
  end
  else r.v <- 0.

(* 18: pairs of 2 x 1 rectangles in a basket weave: along x, along z *)
let rectangle_pair =
  boxes 4 ~scale:0.5
    [ along_z 0.5 1.; along_z 1.5 1.; along_x 3. 0.5; along_x 3. 1.5; along_x 1. 2.5; along_x 1. 3.5; along_z 2.5 3.;
      along_z 3.5 3. ]

(* 19 and 20: hexagons, each surrounded by triangles (the snub
   hexagonal tiling, sides 1), right- and left-handed: triangles up and
   down, then hexagons. Rows of height 3 sqrt3/2 shifted by half a unit
   along x each (the row number by POV-Ray's integer arithmetic), then
   the period of 7 along x cut into pieces moved onto two hexagons. *)
let hexagon_triangle_snub ~right (p : Vec3.m) (r : result) =
  let row = truncate (p.mz /. s3_2) / 3 in
  let row = if p.mz < 0. then row - 1 else row in
  let shift = float_of_int row /. 2. in
  let x = if right then p.mx +. shift else p.mx -. shift in
  let z = ref (p.mz -. (3. *. s3_2 *. Float.floor (p.mz /. (3. *. s3_2)))) in
  let x = ref (wrap (x +. 7.) 7.) in
  if right then begin
    if !x > 4.5 && !z > s3 then (x := !x -. 4.5; z := !z -. s3_2);
    if !x > 5. && !z < s3_2 then (x := !x -. 5.; z := !z +. s3);
    if !x > 2.5 && !z < s3 then (x := !x -. 2.5; z := !z +. s3_2)
  end
  else begin
    if !x > 2. && !z < s3_2 then (x := !x -. 2.; z := !z +. s3);
    if !x > 4.5 && !z < s3 then (x := !x -. 4.5; z := !z +. s3_2);
    if !x > 2.5 && !z > s3 then (x := !x -. 2.5; z := !z -. s3_2)
  end;
  let band = truncate (!z /. s3_2) in
  let flip = if band = 2 then 1 else 0 in
  let band = if band = 2 then 1 else band in
  let x = !x and z = if flip = 1 then (2. *. s3) -. !z else !z in
  if band = 0 || x > 2. || z +. (s3 *. x) < s3 || (s3 *. x) -. z > s3 then
    r.v <- triangle_fold ~edge_flips:true x z flip /. 3.
  else begin
    let z = z -. s3_2 in
    let x = if x > 1. then 2. -. x else x in
    r.v <- hex_band x z 2.000001 /. 3.
  end

(* 21: squares and triangles (the snub square tiling, sides 1): the
   triangles by their four orientations, then the squares by their two
   (bands of 1/6). The plane is cut in squares of side 1 + sqrt3 folded
   about their centre lines into the quarter [0, (1 + sqrt3)/2]^2, which
   is turned or mirrored onto one triangle and a quarter square. *)
let square_triangle_snub (p : Vec3.m) (r : result) =
  let period = 1. +. s3 and half = 0.5 +. s3_2 in
  let x = ref (wrap p.mx period) and z = ref (wrap p.mz period) in
  let odd = ref 0 and mirrored = ref false in
  if !z > half then begin
    z := 1. +. s3 -. !z;
    odd := 1 - !odd
  end;
  if !x > half then begin
    x := 1. +. s3 -. !x;
    odd := 1 - !odd;
    mirrored := true
  end;
  let beyond_x = (2. *. !x) +. ((s3 -. 1.) *. 2. *. !z /. (s3 +. 1.)) > s3
  and beyond_z = (2. *. !z *. s3) +. ((s3 -. 3.) *. 2. *. !x /. (s3 +. 1.)) > s3 in
  let m = !mirrored and d = !odd in
  let orient =
    match (beyond_x, beyond_z) with
    | false, false -> if m then 2 else 0
    | true, false ->
        let x0 = !x in
        x := !z;
        z := half -. x0;
        if m then 1 + (2 * d) else 3 - (2 * d)
    | false, true ->
        let z0 = !z in
        z := !x;
        x := half -. z0;
        if m then 3 - (2 * d) else 1 + (2 * d)
    | true, true ->
        x := half -. !x;
        z := half -. !z;
        if m then 0 else 2
  in
  if !x = 0. then (x := 0.; z := 0.);
  let s = (!z *. 2. *. s3) -. s3 +. (!x *. 2.) in
  if s < 0. then begin
    let d1 = -1.5 /. s3 *. s and d2 = 2. *. !x *. s3 in
    r.v <- (float_of_int orient +. 1. -. mn d1 d2) /. 6.
  end
  else begin
    let s = mn (s *. (1.5 /. s3)) 1. in
    if d = 1 then r.v <- mn (mx ((-1. *. s +. 6.) /. 6.) (5.000001 /. 6.)) 1.
    else r.v <- mx (mn ((-1. *. s +. 5.) /. 6.) (5. /. 6.)) (4.000001 /. 6.)
  end

(* 22: dodecagons with triangles between them (the truncated hexagonal
   tiling, sides 1): triangles up and down, then dodecagons *)
let dodecagon_triangle (p : Vec3.m) (r : result) =
  let x = ref (wrap p.mx (2. +. s3)) and z = ref (wrap p.mz (3. +. (2. *. s3))) in
  let flip = ref 0 in
  if !z > s3 +. 1.5 then begin
    z := !z -. (s3 +. 1.5);
    x := !x +. ((if !x < 1. +. s3_2 then 1. else -1.) *. (1. +. s3_2))
  end;
  if !x > 1. +. s3_2 then x := 2. +. s3 -. !x;
  if !z > 1. +. s3_2 then begin
    z := 2. +. s3 -. !z;
    flip := 1 - !flip
  end;
  let d2 = !x -. s3_2 -. 0.5 +. (!z *. s3) in
  let d2 =
    if d2 < 0. then begin
      (* below the slanted side: turned by -120 degrees about the
         corner's triangle *)
      let x0 = !x and z0 = !z in
      x := ((1. +. s3) /. 4.) +. (0.5 *. x0) -. (s3_2 *. z0);
      z := ((3. +. s3) /. 4.) -. (s3_2 *. x0) -. (0.5 *. z0);
      -1. *. d2
    end
    else d2
  in
  let x = !x and z = !z in
  let d3 = (z -. s3_2 -. 0.5 +. (x *. s3)) *. s3 in
  if d3 < 0. then r.v <- (mx d3 (-1.) +. float_of_int (1 + !flip)) /. 3.
  else begin
    let d = mn (mn (mn (mn (z *. 3.) (d2 *. s3)) d3) (x *. 3.)) 1. in
    r.v <- (3.0000001 -. d) /. 3.
  end

(* 23 and 24: dodecagons, hexagons and squares (the truncated
   trihexagonal tiling, sides 1): hexagons, squares, dodecagons (24:
   hexagons, then the squares by their three orientations, then the
   dodecagons, in fifths) *)
let dodecagon_hexagon ~five (p : Vec3.m) (r : result) =
  let x = ref (wrap p.mx (3. +. s3)) and z = ref (wrap p.mz (3. +. (3. *. s3))) in
  let mir_x = ref 0 and mir_z = ref 0 in
  if !z > (1.5 *. s3) +. 1.5 then begin
    z := !z -. ((1.5 *. s3) +. 1.5);
    x := !x +. ((if !x < 1.5 +. s3_2 then 1. else -1.) *. (1.5 +. s3_2))
  end;
  if !x > 1.5 +. s3_2 then begin
    x := 3. +. s3 -. !x;
    mir_x := 1 - !mir_x
  end;
  if !z > 1. +. s3 then begin
    z := 2. +. (2. *. s3) -. !z;
    mir_z := 1 - !mir_z
  end;
  if !x -. s3_2 -. 1.5 +. (!z *. s3) < 0. then begin
    let x0 = !x and z0 = !z in
    x := ((3. +. s3) /. 4.) +. (0.5 *. x0) -. (s3_2 *. z0);
    z := ((3. +. (3. *. s3)) /. 4.) -. (s3_2 *. x0) -. (0.5 *. z0)
  end;
  let x = !x and z = !z in
  let d1 = (z *. 2.) -. s3 and d2 = x -. s3_2 -. 2.5 +. (z *. s3)
  and d3 = z -. (1.5 *. s3) -. 0.5 +. (x *. s3) and d4 = (x -. 0.5) *. 2. in
  let bands = if five then 5. else 3. in
  let v =
    if d2 >= 0. && d1 >= 0. && d3 >= 0. && d4 >= 0. then
      (* the dodecagon *)
      (if five then 5.000001 else 3.000001) -. mn (mn (mn (mn d1 d2) d3) d4) 1.
    else begin
      let d5 = (2. *. z) -. (2. *. s3) -. 1. in
      if d5 >= 0. then 2. -. mn d5 (-1. *. d4)
      else begin
        let d6 = (s3 *. x) -. z -. s3_2 +. 0.5 in
        let d7 = d6 -. 2. in
        if d6 < 0. && not (d7 >= 0.) then 1. -. mn (mn (mn (-1. *. d6) (-1. *. d3)) (-1. *. d5)) 1.
        else if d6 >= 0. && d7 >= 0. then 1. -. mn (mn d7 (-1. *. d1)) 1.
        else
          (* a slanted square *)
          let m = mn (mn d6 (-1. *. d2)) (-1. *. d7) in
          if five then float_of_int ((!mir_z + !mir_x) mod 2) +. 3. -. m else 2. -. m
      end
    end
  in
  r.v <- v /. bands

(* The Penrose tilings, by the angles of multiples of 18 degrees and
   the golden ratio. *)
let sin18 = 0.30901699437494742410
let sin36 = 0.58778525229247312917
let sin54 = 0.80901699437494742410
let sin72 = 0.95105651629515357212
let tan18 = 0.32491969623290632616
let tan36 = 0.72654252800536088590
let tan54 = 1.3763819204711735382
let tan72 = 3.0776835371752534026
let cos18 = sin72
let cos36 = sin54
let cos72 = sin18
let sin108 = sin72
let cos108 = -.cos72
let tan108 = -.tan72
let sin144 = sin36
let cos144 = -.cos36
let tan126 = -.tan54
let tan144 = -.tan36
let sin162 = sin18
let cos162 = -.cos18
let tan162 = -.tan18
let phi = 1.6180339887498948482 (* the golden ratio *)
let inv_phi = 0.61803398874989484820
let phi2 = 2.6180339887498948482
let inv_phi2 = 0.38196601125010515180

(* POV-Ray's margin that keeps a tile's values inside its band *)
let margin = 1e-6

(* a point's distance from the origin below which the Penrose tilings
   give 1 (POV-Ray's EPSILON) *)
let centre_eps = 1e-10

(* the point turned into the sector of the pentagon's symmetry around
   the +x axis (|angle| <= 36 degrees): z made positive, then turned by
   72 or 144 degrees where the angle is larger; [r] its distance from
   the origin. Into [t] (a point on the stack would be boxed). *)
let[@inline] fold5 (t : Vec3.m) r =
  let x = t.mx and z = Float.abs t.mz in
  if x < r *. cos36 then begin
    let far = x < r *. cos108 in
    let s = if far then sin144 else sin72 and c = if far then cos144 else cos72 in
    t.mx <- (x *. c) +. (z *. s);
    t.mz <- Float.abs ((z *. c) -. (x *. s))
  end
  else t.mz <- z

let scratch = Scratch.key (fun () -> Vec3.m ())

(* 26 and 27: Penrose's kites and darts (P2), or rhombs (P3): the
   point taken into the sector of the central star (26, five darts) or
   of the five wide rhombs and the decagon around them (27), then
   followed down the half-kites and half-darts of the deflation, one
   level a step, the half-tile it ends in giving the value: darts then
   kites, wide then narrow rhombs. POV-Ray's factors 4.46 and 5.55 set
   the width of the values near the sides. *)
let penrose ~rhombs (p : Vec3.m) (r : result) =
  let rr = Float.sqrt ((p.mx *. p.mx) +. (p.mz *. p.mz)) in
  if rr <= centre_eps then r.v <- 1.
  else begin
    let t = Scratch.get scratch in
    Vec3.set t p.mx 0. p.mz;
    fold5 t rr;
    let x = ref t.mx and z = ref t.mz in
    if rhombs then (x := !x *. inv_phi; z := !z *. inv_phi);
    let dist = Float.abs ((sin108 *. !x) -. (cos108 *. !z)) /. cos18 in
    let depth = if dist > 0. then Int.max 0 (truncate (Float.ceil (Float.log dist /. Float.log phi2))) else 0 in
    let k = Float.pow inv_phi2 (float_of_int depth) in
    x := !x *. k;
    z := !z *. k;
    if depth mod 2 = 1 then begin
      let x0 = !x and z0 = !z in
      x := (x0 *. cos36) +. (z0 *. sin36);
      z := Float.abs ((z0 *. cos36) -. (x0 *. sin36))
    end;
    let depth = ref (2 * depth) and kite = ref true in
    while !depth > 0 do
      let x0 = !x and z0 = Float.abs !z in
      if !kite then begin
        if z0 < (x0 -. inv_phi) *. tan144 then begin
          kite := false;
          x := x0 *. phi;
          z := z0 *. phi
        end
        else begin
          let xc = x0 -. cos36 and zc = z0 -. sin36 in
          x := ((xc *. cos108) -. (zc *. sin108)) *. phi;
          z := ((zc *. cos108) +. (xc *. sin108)) *. phi
        end
      end
      else if z0 < (x0 -. inv_phi) *. tan108 then begin
        kite := true;
        x := ((x0 *. cos36) +. (z0 *. sin36)) *. phi;
        z := ((z0 *. cos36) -. (x0 *. sin36)) *. phi
      end
      else begin
        let xc = x0 -. 1. in
        x := ((xc *. cos144) +. (z0 *. sin144)) *. phi;
        z := ((z0 *. cos144) -. (xc *. sin144)) *. phi
      end;
      decr depth
    done;
    let x = !x and z = Float.abs !z in
    if !kite then begin
      if rhombs then begin
        let slant = Float.abs ((sin72 *. (x -. inv_phi)) -. (cos72 *. z)) *. 5.55 in
        if z < (x -. inv_phi) *. tan72 then begin
          let b = Float.abs ((sin108 *. (x -. 1.)) -. (cos108 *. z)) *. 5.55 in
          r.v <- mx (mx (1. -. (slant /. 2.)) (1. -. (b /. 2.))) (0.5 +. margin)
        end
        else begin
          let a = Float.abs z *. 5.55 in
          r.v <- mn (mx (mx (0.5 -. (a /. 2.)) (0.5 -. (slant /. 2.))) 0.) (0.5 -. margin)
        end
      end
      else begin
        let a = Float.abs ((sin36 *. x) -. (cos36 *. z)) *. 4.46
        and b = Float.abs ((sin108 *. (x -. 1.)) -. (cos108 *. z)) *. 4.46 in
        r.v <- mn (mx (mx (0.5 -. (a /. 2.)) (0.5 -. (b /. 2.))) 0.) (0.5 -. margin)
      end
    end
    else if rhombs then begin
      let a = Float.abs ((sin36 *. x) -. (cos36 *. z)) *. 5.55
      and b = Float.abs ((sin144 *. (x -. 1.)) -. (cos144 *. z)) *. 5.55 in
      r.v <- mn (mx (mx (0.5 -. (a /. 2.)) (0.5 -. (b /. 2.))) 0.) (0.5 -. margin)
    end
    else begin
      let a = Float.abs z *. 4.46 and b = Float.abs ((sin144 *. (x -. 1.)) -. (cos144 *. z)) *. 4.46 in
      r.v <- mx (mx (1. -. (a /. 2.)) (1. -. (b /. 2.))) (0.5 +. margin)
    end
  end

(* 25: Penrose's pentagons, stars, boats and diamonds (P1), a pentagon
   at the centre: the point taken into the central pentagon's sector and
   down the deflation, four levels a step of the golden ratio squared,
   each level a change of tile (and a flag: a pentagon inside a quad or
   a wedge, a diamond's side), the tile it ends in giving the value:
   pentagons of three kinds, stars, boats, diamonds (bands of 1/6). *)
let pentagon1 = 0
let pentagon2 = 1
let pentagon3 = 2
let star = 3
let boat = 4
let diamond = 5

(* the distance across a pentagon's side, scaled by POV-Ray's 5.55 *)
let[@inline] pentagon_side x = Float.abs (x -. (0.5 /. tan36)) *. 5.55 *. inv_phi
let[@inline] star_side x z = Float.abs ((sin162 *. (x -. (phi *. 0.5 /. sin36))) -. (cos162 *. z)) *. 5.55 *. inv_phi
(* [v] kept within [lo, hi], into [r] (stored from the comparisons
   themselves: bounds folded into constants, joined with [v] in a value
   bound by [let], would box it) *)
let[@inline] clamp_into (r : result) v lo hi = r.v <- (if v >= hi then hi else if v > lo then v else lo)

(* the band [lo/6, (lo+1)/6] of tile [lo] of the six, [d] into it *)
let[@inline] band6 (r : result) lo d =
  clamp_into r (((lo +. 1.) /. 6.) -. (d /. 6.)) ((lo /. 6.) +. margin) (((lo +. 1.) /. 6.) -. margin)

let penrose1 (p : Vec3.m) (r : result) =
  let rr = Float.sqrt ((p.mx *. p.mx) +. (p.mz *. p.mz)) in
  if rr <= centre_eps then r.v <- 1.
  else begin
    let t = Scratch.get scratch in
    Vec3.set t p.mx 0. p.mz;
    fold5 t rr;
    let dist = t.mx *. 2. *. tan36 in
    let depth = if dist > 0. then Int.max 0 (truncate (Float.ceil (Float.log dist /. Float.log (phi2 *. phi2)))) else 0 in
    let k = Float.pow (inv_phi2 *. inv_phi2) (float_of_int depth) in
    let x = ref (t.mx *. k) and z = ref (t.mz *. k) in
    let depth = ref (4 * depth) and tile = ref pentagon1 and flag = ref false in
    (* one step: the tile [next] (with [f]) at (x, z) times phi *)
    let q = inv_phi2 *. 0.5 /. sin36 in
    while !depth > 0 do
      let x0 = !x and z0 = Float.abs !z in
      let next = ref pentagon1 and f = ref false and nx = ref x0 and nz = ref z0 in
      (match !tile with
      | 0 ->
          Vec3.set t x0 0. z0;
          fold5 t (Float.sqrt ((x0 *. x0) +. (z0 *. z0)));
          let x1 = t.mx and z1 = t.mz in
          if z1 < ((x1 -. (0.5 /. tan36)) *. tan54) +. 0.5 then begin
            next := pentagon2;
            nx := x1 -. (0.5 /. tan36) -. (inv_phi *. 0.5 *. cos72 /. sin36);
            nz := z1
          end
          else begin
            next := star;
            nx := (x1 *. cos36) +. (z1 *. sin36);
            nz := (z1 *. cos36) -. (x1 *. sin36)
          end
      | 1 ->
          if !flag then begin
            if z0 < (x0 -. q) *. tan54 then (next := pentagon1; nx := x0 -. (0.5 /. sin36))
            else if z0 < (x0 -. q) *. tan162 then (next := diamond; f := true; nx := -1. *. x0)
            else begin
              next := pentagon2;
              f := true;
              nx := (x0 *. cos108) -. (z0 *. sin108) +. (inv_phi *. 0.5 /. sin36);
              nz := (z0 *. cos108) +. (x0 *. sin108)
            end
          end
          else if z0 < (x0 +. (0.5 /. sin36)) *. tan18 then begin
            next := diamond;
            nx := x0 +. (0.5 /. sin36) -. q
          end
          else begin
            next := pentagon3;
            nx := -1. *. ((x0 *. cos36) +. (z0 *. sin36)) -. (cos72 *. 0.5 /. sin36);
            nz := (z0 *. cos36) -. (x0 *. sin36) -. (sin72 *. 0.5 /. sin36)
          end
      | 2 ->
          let w = inv_phi2 *. 0.5 *. cos72 /. sin36 in
          if !flag && x0 > w then begin
            next := pentagon2;
            f := true;
            nx := -1. *. (x0 -. w -. (inv_phi *. 0.5 /. tan36))
          end
          else if (not !flag) && x0 < 0.5 *. cos108 /. sin36 then begin
            next := pentagon2;
            nx := (x0 *. cos144) +. (z0 *. sin144) -. (0.5 /. sin36);
            nz := (z0 *. cos144) -. (x0 *. sin144)
          end
          else if (not !flag) && z0 > (x0 -. q) *. tan126 then begin
            next := pentagon3;
            nx := -1. *. ((x0 *. cos36) -. (z0 *. sin36)) -. (cos72 *. 0.5 /. sin36);
            nz := (z0 *. cos36) +. (x0 *. sin36) -. (sin72 *. 0.5 /. sin36)
          end
          else (next := boat; f := !flag)
      | 3 ->
          if x0 < inv_phi *. 0.5 /. tan36 then next := pentagon1
          else begin
            next := pentagon3;
            f := true;
            nx := -1. *. (x0 -. (inv_phi /. tan36))
          end
      | 4 ->
          if !flag && x0 > phi *. 0.5 *. cos108 /. sin36 then (next := pentagon1; nx := -1. *. x0)
          else begin
            next := pentagon3;
            f := true;
            if not !flag then begin
              nx := (x0 *. cos72) -. (z0 *. sin72);
              nz := (z0 *. cos72) +. (x0 *. sin72)
            end;
            nx := !nx +. (0.5 /. sin36)
          end
      | _ -> if !flag then next := pentagon1 else (next := pentagon3; f := true));
      tile := !next;
      flag := !f;
      x := !nx *. phi;
      z := !nz *. phi;
      decr depth
    done;
    let x0 = !x and z0 = Float.abs !z in
    match !tile with
    | 0 | 1 | 2 ->
        Vec3.set t x0 0. z0;
        fold5 t (Float.sqrt ((x0 *. x0) +. (z0 *. z0)));
        let d = pentagon_side t.mx in
        if !tile = 0 then clamp_into r ((1. /. 6.) -. (d /. 6.)) 0. ((1. /. 6.) -. margin)
        else band6 r (float_of_int !tile) d
    | 3 -> band6 r 3. (star_side x0 z0)
    | 4 ->
        let d1 = Float.abs (x0 -. (inv_phi *. 0.5 *. cos72 /. sin36)) *. 5.55 *. inv_phi in
        Vec3.set t (-1. *. x0) 0. z0;
        fold5 t (Float.sqrt ((x0 *. x0) +. (z0 *. z0)));
        let d2 = star_side t.mx t.mz in
        clamp_into r (mx ((5. /. 6.) -. (d1 /. 6.)) ((5. /. 6.) -. (d2 /. 6.))) ((4. /. 6.) +. margin) ((5. /. 6.) -. margin)
    | _ ->
        let d = Float.abs ((sin18 *. (x0 +. (inv_phi *. 0.5 /. sin36))) -. (cos18 *. z0)) *. 5.55 *. inv_phi in
        band6 r 5. d
  end

(* The tiling [n] (1 to 27) at [p] (x and z; y does not matter), into
   [r]. *)
let eval n (p : Vec3.m) (r : result) =
  match n with
  | 1 -> square p r
  | 2 -> hexagon p r
  | 3 -> triangle p r
  | 4 -> lozenge p r
  | 5 -> rhombus p r
  | 6 -> boxes_value rectangles p r
  | 7 -> octagon_square p r
  | 8 -> square_triangle p r
  | 9 -> hexagon_triangle p r
  | 10 -> square_offset p r
  | 11 -> square_rectangle p r
  | 12 -> rectangle_square p r
  | 13 -> square_internal p r
  | 14 -> square_internal_5 p r
  | 15 -> boxes_value square_double p r
  | 16 -> hexagon_square_triangle ~six:false p r
  | 17 -> hexagon_square_triangle ~six:true p r
  | 18 -> boxes_value rectangle_pair p r
  | 19 -> hexagon_triangle_snub ~right:true p r
  | 20 -> hexagon_triangle_snub ~right:false p r
  | 21 -> square_triangle_snub p r
  | 22 -> dodecagon_triangle p r
  | 23 -> dodecagon_hexagon ~five:false p r
  | 24 -> dodecagon_hexagon ~five:true p r
  | 25 -> penrose1 p r
  | 26 -> penrose ~rhombs:false p r
  | 27 -> penrose ~rhombs:true p r
  | _ -> invalid_arg "Tiling.eval: a tiling is 1 to 27"

let count = 27

(* the number of kinds of tile (bands of the value) of each tiling *)
let bands n =
  match n with
  | 1 | 2 | 4 | 10 -> 1
  | 3 | 6 | 7 | 15 | 18 | 26 | 27 -> 2
  | 5 | 8 | 9 | 11 | 12 | 13 | 16 | 19 | 20 | 22 | 23 -> 3
  | 14 | 24 -> 5
  | 17 | 21 | 25 -> 6
  | _ -> invalid_arg "Tiling.bands: a tiling is 1 to 27"
