(* POV-Ray 3.7's radiosity: settings, gather directions, per-domain
   depth (see radiosity.mli). *)

(* A cached gather: where, about which normal, the light found (before
   gray_threshold and brightness), the harmonic mean distance of what its
   rays met, the nearest distance and the direction toward it *)
type record = {
  px : float; py : float; pz : float;
  nx : float; ny : float; nz : float;
  ir : float; ig : float; ib : float;
  hmd : float;
  near : float;
  tx : float; ty : float; tz : float;
}

let levels = 128 (* L from -64 to 63 *)

(* the records of one recursion depth, in cells of side 2^L (L by each
   record's reach: at least the reach, less than twice it), each record
   in every cell its reach touches, so that a lookup reads one cell per
   level: the records within a reach of it and few more (a record kept
   in only the cell of its centre needs the 8 cells about a point read,
   and those hold some 10 times the records that serve it). Keyed by
   (L, cell) mixed into one int: a table of its own, open addressing
   over an array of keys and counts side by side (a slot is free while
   its count is 0: one cache line read for both) and one of cells, so that a
   lookup is a few integer operations with no call (the standard table,
   polymorphic, calls C to hash each key and [compare_val] to compare: a
   fifth of radiosity2.pov's time; made for ints by its functor, it
   calls [hash] and [equal] as closures). [levels] holds the levels in
   use, the first [nlevels] of it, in increasing order. *)
type store = {
  mutable slots : int array;  (* slot i: its key at 2i, the records in its cell at 2i + 1 (0: free) *)
  mutable cells : Float.Array.t array;  (* a cell's records, [width] floats each, oldest first *)
  mutable filled : int;  (* slots in use *)
  mutable levels : int array;
  mutable nlevels : int;
  mutable n : int;
  mutable used : int array;  (* the slots filled, the first [filled] of it *)
}

(* a record in a cell: its 14 fields in the order a lookup's test reads
   them (the point and harmonic mean distance, that most records fail
   on, side by side: one cache line, where they were 72 bytes apart):
   the point at [f_p], the fields named as in [record] *)
let width = 14
let f_p = 0
let f_hmd = 3
let f_near = 4
let f_t = 5
let f_n = 8
let f_i = 11

let no_cell = Float.Array.make 0 0.

let new_store () =
  { slots = Array.make 512 0; cells = Array.make 256 no_cell; filled = 0; levels = [||];
    nlevels = 0; n = 0; used = Array.make 128 0 }

let[@inline] mix k =
  let h = k * 0x1E3779B97F4A7C15 in
  h lxor (h lsr 31)

let[@inline] size st = Array.length st.cells

(* the slot of key [k]: its own, or the free one where it would go *)
let slot slots k =
  let mask = (Array.length slots / 2) - 1 in
  let i = ref (mix k land mask) in
  while Array.unsafe_get slots ((2 * !i) + 1) > 0 && Array.unsafe_get slots (2 * !i) <> k do
    i := (!i + 1) land mask
  done;
  !i

let rec put st k rc =
  if 2 * (st.filled + 1) > size st then begin
    (* grown to twice the size, the cells moved over as they are *)
    let slots = st.slots and cells = st.cells and used = st.used in
    let n = 2 * size st in
    st.slots <- Array.make (2 * n) 0;
    st.cells <- Array.make n no_cell;
    st.used <- Array.make (n / 2) 0;
    for u = 0 to st.filled - 1 do
      let i = used.(u) in
      let j = slot st.slots slots.(2 * i) in
      st.slots.(2 * j) <- slots.(2 * i);
      st.slots.((2 * j) + 1) <- slots.((2 * i) + 1);
      st.cells.(j) <- cells.(i);
      st.used.(u) <- j
    done;
    put st k rc
  end
  else begin
    let i = slot st.slots k in
    let c = st.slots.((2 * i) + 1) in
    if c = 0 then begin
      (* at most half the slots are filled before the table grows *)
      st.used.(st.filled) <- i;
      st.filled <- st.filled + 1;
      st.slots.(2 * i) <- k;
      (* a cell emptied by [clear_store] is filled again *)
      if Float.Array.length st.cells.(i) = 0 then st.cells.(i) <- Float.Array.make (4 * width) 0.
    end
    else if (c + 1) * width > Float.Array.length st.cells.(i) then begin
      let a = Float.Array.make (2 * c * width) 0. in
      Float.Array.blit st.cells.(i) 0 a 0 (c * width);
      st.cells.(i) <- a
    end;
    let a = st.cells.(i) and o = c * width in
    let set j v = Float.Array.set a (o + j) v in
    set f_p rc.px; set (f_p + 1) rc.py; set (f_p + 2) rc.pz;
    set f_hmd rc.hmd; set f_near rc.near;
    set f_t rc.tx; set (f_t + 1) rc.ty; set (f_t + 2) rc.tz;
    set f_n rc.nx; set (f_n + 1) rc.ny; set (f_n + 2) rc.nz;
    set f_i rc.ir; set (f_i + 1) rc.ig; set (f_i + 2) rc.ib;
    st.slots.((2 * i) + 1) <- c + 1
  end

(* [picture]: the colours the final pass found at the pixels' centres of
   a [pw] x [ph] image, 3 floats a pixel by rows (empty: none) *)
type cache = {
  mutable filling : bool;
  mutable final : bool;
  mutable speculating : bool;
  stores : store array;
  mutable picture : Float.Array.t;
  mutable pw : int;
  mutable ph : int;
}

let new_cache () =
  { filling = false; final = true; speculating = false; stores = Array.init 21 (fun _ -> new_store ());
    picture = Float.Array.make 0 0.; pw = 0; ph = 0 }

type t = {
  count : int;
  recursion_limit : int;
  brightness : float;
  error_bound : float;
  nearest_count : int;
  gray_threshold : float;
  pretrace_start : float;
  pretrace_end : float;
  low_error_factor : float;
  minimum_reuse : float;
  maximum_reuse : float;
  adc_bailout : float;
  max_sample : float;
  always_sample : bool;
  normal : bool;
  media : bool;
  keep_ambient : bool;
  cache : cache;
}

let default =
  {
    count = 35;
    recursion_limit = 2;
    brightness = 1.;
    error_bound = 1.8;
    nearest_count = 5;
    gray_threshold = 0.;
    pretrace_start = 0.08;
    pretrace_end = 0.04;
    low_error_factor = 0.5;
    minimum_reuse = 0.015;
    maximum_reuse = 0.2;
    adc_bailout = 0.01;
    max_sample = -1.;
    always_sample = false;
    normal = false;
    media = false;
    keep_ambient = false;
    cache = new_cache ();
  }

let rays r depth = Int.max 5 (int_of_float (float_of_int r.count *. Float.pow 0.5 (float_of_int depth)))
let trace_level depth = int_of_float (1.5 *. float_of_int (depth + 1)) + 1
let weight r depth = Float.max (r.adc_bailout +. 1e-10) (Float.pow (0.5 *. r.brightness) (float_of_int (depth + 1)))

let radical_inverse i =
  (* the bits of i mirrored about the binary point *)
  let rec go i f acc = if i = 0 then acc else go (i lsr 1) (f *. 0.5) (if i land 1 = 1 then acc +. f else acc) in
  go i 0.5 0.

let[@inline] frac x = x -. Float.floor x

let direction_into (n : Vec3.m) i count r1 r2 (out : Vec3.m) =
  let u1 = frac (((float_of_int i +. 0.5) /. float_of_int count) +. r1) in
  let u2 = frac (radical_inverse i +. r2) in
  let rad = Float.sqrt u1 and phi = 2. *. Float.pi *. u2 in
  let lx = rad *. Float.cos phi and lz = rad *. Float.sin phi in
  let ly = Float.sqrt (Float.max 0. (1. -. u1)) in
  (* POV-Ray's frame: y the normal, x across it and z (or y), z = x × y *)
  let near_z = Float.abs n.mz > 0.9 in
  let oy = if near_z then 1. else 0. and oz = if near_z then 0. else 1. in
  let xx = (n.my *. oz) -. (n.mz *. oy) and xy = -.(n.mx *. oz) and xz = n.mx *. oy in
  let k = 1. /. Float.sqrt ((xx *. xx) +. (xy *. xy) +. (xz *. xz)) in
  let xx = xx *. k and xy = xy *. k and xz = xz *. k in
  let zx = (xy *. n.mz) -. (xz *. n.my) and zy = (xz *. n.mx) -. (xx *. n.mz) and zz = (xx *. n.my) -. (xy *. n.mx) in
  Vec3.set out
    ((lx *. xx) +. (ly *. n.mx) +. (lz *. zx))
    ((lx *. xy) +. (ly *. n.my) +. (lz *. zy))
    ((lx *. xz) +. (ly *. n.mz) +. (lz *. zz))

let depth_key = Scratch.key (fun () -> ref 0)
let depth () = !(Scratch.get depth_key)
let descend () = incr (Scratch.get depth_key)
let ascend () = decr (Scratch.get depth_key)
let reset_depth () = Scratch.get depth_key := 0

let reuse_count r depth = match depth with 0 -> r.nearest_count | 1 -> Int.min 2 r.nearest_count | _ -> 1

(* emptied: only the slots filled, the arrays and the slots' cells kept
   for the records after (a sample's own records and a batch's, cleared
   over and over, seldom fill more than a few slots; radiosity2.pov at
   320x240 on 2 domains: the tables grew 183 times a render when emptied
   back to 256 slots, 11 times this way) *)
let clear_store st =
  for u = 0 to st.filled - 1 do
    let i = st.used.(u) in
    st.slots.(2 * i) <- 0;
    st.slots.((2 * i) + 1) <- 0
  done;
  st.filled <- 0;
  st.nlevels <- 0;
  st.n <- 0

let clear c =
  c.filling <- false;
  c.final <- true;
  c.speculating <- false;
  Array.iter clear_store c.stores;
  c.picture <- Float.Array.make 0 0.;
  c.pw <- 0;
  c.ph <- 0

let records c depth = c.stores.(depth).n

let[@inline] cell_key l ix iy iz =
  (((((l * 1_000_003) + ix) * 1_000_033) + iy) * 998_244_353) + iz

(* 2^-l for the levels l = -64 .. 63: a coordinate over a cell's side
   by one product, exact as the division by 2^l it replaces (both only
   move the exponent) *)
let inv_side = Float.Array.init levels (fun li -> Float.ldexp 1. (64 - li))

(* [int_of_float (Float.floor v)] without the call to C's floor
   ([int_of_float] truncates toward zero; the same int for every [v]
   an int holds) *)
let[@inline] ifloor v =
  let i = int_of_float v in
  if float_of_int i > v then i - 1 else i

(* the level whose cells are at least [reach] across *)
let level_of reach =
  let l = int_of_float (Float.ceil (Float.log2 reach)) in
  Int.max (-64) (Int.min 62 l)

(* level [l] among the store's levels in use, kept in increasing order *)
let use_level st l =
  let rec find i = i < st.nlevels && (st.levels.(i) = l || find (i + 1)) in
  if not (find 0) then begin
    if st.nlevels = Array.length st.levels then
      st.levels <- Array.append st.levels (Array.make (Int.max 4 st.nlevels) 0);
    let i = ref st.nlevels in
    while !i > 0 && st.levels.(!i - 1) > l do
      st.levels.(!i) <- st.levels.(!i - 1);
      decr i
    done;
    st.levels.(!i) <- l;
    st.nlevels <- st.nlevels + 1
  end

let keep st rc reach =
  (* a reach past 2^62 (none a scene makes) kept within the top level *)
  let reach = if reach <= 0x1p62 then reach else 0x1p62 in
  let l = level_of reach in
  let k = Float.Array.get inv_side (l + 64) and s = Float.ldexp 1. l in
  (* the cells the ball of the reach about the record's point touches *)
  let gap v i =
    let a = float_of_int i *. s in
    if v < a then a -. v else if v > a +. s then v -. (a +. s) else 0.
  in
  for ix = ifloor ((rc.px -. reach) *. k) to ifloor ((rc.px +. reach) *. k) do
    let gx = gap rc.px ix in
    for iy = ifloor ((rc.py -. reach) *. k) to ifloor ((rc.py +. reach) *. k) do
      let gy = gap rc.py iy in
      for iz = ifloor ((rc.pz -. reach) *. k) to ifloor ((rc.pz +. reach) *. k) do
        let gz = gap rc.pz iz in
        if (gx *. gx) +. (gy *. gy) +. (gz *. gz) <= reach *. reach then put st (cell_key l ix iy iz) rc
      done
    done
  done;
  use_level st l;
  st.n <- st.n + 1

(* A sample of the pretrace traced ahead of its turn, on any domain:
   the records its gathers make, kept apart ([overlay], and [made] in
   the order they were made), and every lookup it makes, logged as 9
   floats (depth, point, normal, error bound, final rules) *)
type spec = {
  overlay : cache;
  mutable made : (int * record * float) list;  (* newest first *)
  mutable log : Float.Array.t;
  mutable nlog : int;
  mutable depths : int;  (* bit [d] set: a lookup at depth [d] logged *)
  mutable logging : bool;
}

let spec_key =
  Scratch.key (fun () -> { overlay = new_cache (); made = []; log = Float.Array.make 64 0.; nlog = 0; depths = 0; logging = true })

exception Abandoned

(* the most lookups a sample traced ahead logs (72 bytes each): past
   them it is abandoned, to be traced in turn (a scene of count 1000
   gathers at two depths logged 470 MB a batch before the cap) *)
let log_cap = 9 * 8192

let add c depth rc reach =
  if c.speculating then begin
    let sp = Scratch.get spec_key in
    keep sp.overlay.stores.(depth) rc reach;
    sp.made <- (depth, rc, reach) :: sp.made
  end
  else keep c.stores.(depth) rc reach

(* field [i] of the record at [o] in a cell *)
let[@inline] at a o i = Float.Array.unsafe_get a (o + i)

(* POV-Ray's test of one record for the point [q] of normal [n]
   (AverageNearBlock): the weight it gets, 0 when it does not serve; the
   record the [width] floats of [a] from [o] *)
let[@inline] weigh a o (q : Vec3.m) (n : Vec3.m) eb final0 =
  let dx = q.mx -. at a o f_p and dy = q.my -. at a o (f_p + 1) and dz = q.mz -. at a o (f_p + 2) in
  let d2 = (dx *. dx) +. (dy *. dy) +. (dz *. dz) in
  let hmd = at a o f_hmd in
  let quick = hmd *. eb in
  if d2 >= quick *. quick then 0.
  else begin
    let dist = Float.sqrt d2 in
    let far = dist > 1e-6 in
    let ux = if far then dx /. dist else 0. and uy = if far then dy /. dist else 0. and uz = if far then dz /. dist else 0. in
    (* a smaller reach toward the nearest surface the gather met *)
    let cn = if far then (at a o f_t *. ux) +. (at a o (f_t + 1) *. uy) +. (at a o (f_t + 2) *. uz) else 0. in
    let ri = if cn > 0. then (cn *. at a o f_near) +. ((1. -. cn) *. hmd) else hmd in
    if dist >= ri *. eb then 0.
    else begin
      let nx = at a o f_n and ny = at a o (f_n + 1) and nz = at a o (f_n + 2) in
      let dd = (n.mx *. nx) +. (n.my *. ny) +. (n.mz *. nz) in
      let e = (dist /. ri) +. (2. *. Float.sqrt (Float.abs (1. -. dd))) in
      if e >= eb then 0.
      else begin
        (* not a record well in front of the point (it may shadow it) *)
        let front =
          if far then begin
            let hx = n.mx +. nx and hy = n.my +. ny and hz = n.mz +. nz in
            let hl = Float.sqrt ((hx *. hx) +. (hy *. hy) +. (hz *. hz)) in
            if hl > 0. then ((ux *. hx) +. (uy *. hy) +. (uz *. hz)) /. hl else 1.
          end
          else 1.
        in
        if front <= -0.05 then 0.
        else begin
          let t = e /. eb in
          let w =
            if final0 then if t < 0.5 then 1. -. (2. *. t *. t) else 2. *. (1. -. t) *. (1. -. t)
            else 1. -. t
          in
          let w = if front <= 0. then w *. (1. -. (front /. -0.05)) else w in
          if w > 0.001 then w else 0.
        end
      end
    end
  end

type sums = { mutable eb : float; mutable ws : float; mutable sr : float; mutable sg : float; mutable sb : float }

let new_sums () = { eb = 0.; ws = 0.; sr = 0.; sg = 0.; sb = 0. }
let sums_key = Scratch.key new_sums
let sums () = Scratch.get sums_key

(* a cell's [count] records (a loop with nothing boxed) *)
let weigh_all (sm : sums) a count (q : Vec3.m) (n : Vec3.m) final0 =
  for i = 0 to count - 1 do
    let o = i * width in
    let w = weigh a o q n sm.eb final0 in
    if w > 0. then begin
      sm.ws <- sm.ws +. w;
      sm.sr <- sm.sr +. (w *. at a o f_i);
      sm.sg <- sm.sg +. (w *. at a o (f_i + 1));
      sm.sb <- sm.sb +. (w *. at a o (f_i + 2))
    end
  done

let[@inline] weigh_level sm st l (q : Vec3.m) n final0 =
  let k = Float.Array.unsafe_get inv_side (l + 64) in
  let i = slot st.slots (cell_key l (ifloor (q.mx *. k)) (ifloor (q.my *. k)) (ifloor (q.mz *. k))) in
  let c = Array.unsafe_get st.slots ((2 * i) + 1) in
  if c > 0 then weigh_all sm (Array.unsafe_get st.cells i) c q n final0

(* every level of a store in use, in increasing order *)
let weigh_levels sm st q n final0 =
  for u = 0 to st.nlevels - 1 do
    weigh_level sm st (Array.unsafe_get st.levels u) q n final0
  done

let log_lookup sp depth (q : Vec3.m) (n : Vec3.m) eb final0 =
  if sp.nlog + 9 > log_cap then raise Abandoned;
  if sp.nlog + 9 > Float.Array.length sp.log then begin
    let log = Float.Array.make (2 * Float.Array.length sp.log) 0. in
    Float.Array.blit sp.log 0 log 0 sp.nlog;
    sp.log <- log
  end;
  let a = sp.log and i = sp.nlog in
  Float.Array.set a i (float_of_int depth);
  Float.Array.set a (i + 1) q.mx;
  Float.Array.set a (i + 2) q.my;
  Float.Array.set a (i + 3) q.mz;
  Float.Array.set a (i + 4) n.mx;
  Float.Array.set a (i + 5) n.my;
  Float.Array.set a (i + 6) n.mz;
  Float.Array.set a (i + 7) eb;
  Float.Array.set a (i + 8) (if final0 then 1. else 0.);
  sp.nlog <- i + 9;
  sp.depths <- sp.depths lor (1 lsl depth)

(* a speculating lookup: the cache's records and the sample's own, level
   by level in increasing order, the sample's own last in a level (in
   the cache of a sample traced in turn they would be at the end of
   their cells: the same sums, added in the same order) *)
let lookup_ahead c depth q n sm final0 =
  let sp = Scratch.get spec_key in
  if sp.logging then log_lookup sp depth q n sm.eb final0;
  let st = c.stores.(depth) and ov = sp.overlay.stores.(depth) in
  let i = ref 0 and j = ref 0 in
  while !i < st.nlevels || !j < ov.nlevels do
    let a = if !i < st.nlevels then Array.unsafe_get st.levels !i else max_int in
    let b = if !j < ov.nlevels then Array.unsafe_get ov.levels !j else max_int in
    if a <= b then begin
      weigh_level sm st a q n final0;
      incr i
    end;
    if b <= a then begin
      weigh_level sm ov b q n final0;
      incr j
    end
  done

let lookup c depth (q : Vec3.m) (n : Vec3.m) (sm : sums) (out : Color.acc) =
  let st = c.stores.(depth) in
  sm.ws <- 0.;
  sm.sr <- 0.;
  sm.sg <- 0.;
  sm.sb <- 0.;
  let final0 = c.final && depth = 0 in
  if c.speculating then lookup_ahead c depth q n sm final0
  else if st.n > 0 then weigh_levels sm st q n final0;
  if sm.ws > 0. then Color.acc_set out (sm.sr /. sm.ws) (sm.sg /. sm.ws) (sm.sb /. sm.ws)

(* Samples traced ahead, then taken in turn *)

type outcome = {
  mutable records : (int * record * float) list;
  mutable lookups : Float.Array.t;
  mutable nlookups : int;
  mutable depths : int;  (* as [spec]'s *)
}

let outcome () = { records = []; lookups = Float.Array.make 64 0.; nlookups = 0; depths = 0 }

let speculate c b = c.speculating <- b

let begin_sample ?(ahead = true) () =
  let sp = Scratch.get spec_key in
  sp.logging <- ahead;
  if (match sp.made with [] -> false | _ :: _ -> true) then Array.iter (fun st -> if st.n > 0 then clear_store st) sp.overlay.stores;
  sp.made <- [];
  sp.nlog <- 0;
  sp.depths <- 0

(* the log handed over to [o], [o]'s old one kept for the next sample *)
let end_sample o =
  let sp = Scratch.get spec_key in
  let log = o.lookups in
  o.records <- List.rev sp.made;
  o.lookups <- sp.log;
  o.nlookups <- sp.nlog;
  o.depths <- sp.depths;
  sp.log <- log;
  begin_sample ()

(* the records taken in turn so far in a batch of samples, and the sums
   and vectors its test reads through *)
type batch = { taken : cache; mutable bdepths : int; bsm : sums; bq : Vec3.m; bn : Vec3.m }

let batch () =
  { taken = new_cache (); bdepths = 0; bsm = new_sums ();
    bq = { Vec3.mx = 0.; my = 0.; mz = 0. }; bn = { Vec3.mx = 0.; my = 0.; mz = 0. } }

let start_batch b =
  Array.iter (fun st -> if st.n > 0 then clear_store st) b.taken.stores;
  b.bdepths <- 0

(* whether a record taken in the batch weighs in one of the lookups;
   the log not walked when none was at a depth with records taken (most
   of the final pass's samples, their batch having taken no record yet:
   one test, not a walk of its log) *)
let conflicts b o =
  o.depths land b.bdepths <> 0
  &&
  let a = o.lookups and sm = b.bsm and q = b.bq and n = b.bn in
  let rec from i =
    i < o.nlookups
    &&
    let st = b.taken.stores.(int_of_float (Float.Array.get a i)) in
    (st.n > 0
    && begin
      Vec3.set q (Float.Array.get a (i + 1)) (Float.Array.get a (i + 2)) (Float.Array.get a (i + 3));
      Vec3.set n (Float.Array.get a (i + 4)) (Float.Array.get a (i + 5)) (Float.Array.get a (i + 6));
      sm.eb <- Float.Array.get a (i + 7);
      sm.ws <- 0.;
      weigh_levels sm st q n (Float.Array.get a (i + 8) = 1.);
      sm.ws > 0.
    end)
    || from (i + 9)
  in
  from 0

let commit c b o =
  List.iter
    (fun (depth, rc, reach) ->
      keep c.stores.(depth) rc reach;
      keep b.taken.stores.(depth) rc reach;
      b.bdepths <- b.bdepths lor (1 lsl depth))
    o.records

let set_picture c ~width ~height p =
  if Float.Array.length p <> 3 * width * height then invalid_arg "Radiosity.set_picture";
  c.picture <- p;
  c.pw <- width;
  c.ph <- height

let picture_into c ~width ~height x y (out : Color.acc) =
  width = c.pw && height = c.ph && x >= 0 && x < width && y >= 0 && y < height
  && begin
    Color.acc_load c.picture ((y * width) + x) out;
    true
  end

let filling c = c.filling
let set_filling c b = c.filling <- b
let final c = c.final
let set_final c b = c.final <- b
