type flags = {
  target : float;
  refraction : int;
  reflection : int;
  collect : bool;
  pass_through : bool;
  split_union : bool;
  area_light : bool;
}

let none =
  { target = 0.; refraction = 0; reflection = 0; collect = true; pass_through = false; split_union = true;
    area_light = false }

let pushed ~parent c =
  {
    c with
    target = (if parent.target > 0. then parent.target else c.target);
    refraction = (if parent.refraction <> 0 then parent.refraction else c.refraction);
    reflection = (if parent.reflection <> 0 then parent.reflection else c.reflection);
    collect = parent.collect && c.collect;
    pass_through = parent.pass_through || c.pass_through;
    split_union = parent.split_union && c.split_union;
  }

(* POV-Ray merges the light's and the target's words (a bit set by
   either), then asks for one of them on and not off *)
let merged a b = (a > 0 || b > 0) && not (a < 0 || b < 0)
let shoots o ~light = merged o.refraction light.refraction || merged o.reflection light.reflection

(* on at the surface unless the light says off, or on at the light
   unless the surface says off *)
let interacts o l = (o > 0 && l >= 0) || (o >= 0 && l > 0)
let refracts o ~light = interacts o.refraction light.refraction
let reflects o ~light = interacts o.reflection light.reflection
let blocks_shadow o ~light = o.target > 0. && merged o.refraction light.refraction

(* the tree: photons in kd order, three floats each *)
type map = {
  n : int;
  pos : Float.Array.t;
  col : Float.Array.t;
  dir : Float.Array.t;
  axis : Bytes.t;  (** the split axis of each node (the photon at the middle of its range) *)
  r0 : float;  (** the gather radius *)
  gmin : int;
  gmax : int;
  tolerance : float;
  emin : int;
}

type settings = {
  spacing : float;
  count : int;
  gather_min : int;
  gather_max : int;
  jitter : float;
  max_trace_level : int;
  adc_bailout : float;
  autostop : float;
  expand_tolerance : float;
  expand_min : int;
  radius : float;
  radius_mult : float;
  media_steps : int;
  media_factor : float;
  media_radius : float;
  media_mult : float;
  state : state;
}

and state = { mutable map : map option; mutable media_map : map option }

let default_settings () =
  { spacing = 1.; count = 0; gather_min = 20; gather_max = 100; jitter = 0.4; max_trace_level = -1;
    adc_bailout = -1.; autostop = 0.5; expand_tolerance = 0.2; expand_min = 35; radius = 0.; radius_mult = 1.;
    media_steps = 0; media_factor = 1.; media_radius = 0.; media_mult = 1.; state = { map = None; media_map = None } }

(* photons as they are shot: growing arrays *)
type store = { mutable data : Float.Array.t; mutable k : int }

let store () = { data = Float.Array.create (9 * 16); k = 0 }

let append st src =
  if src.k > 0 then begin
    let need = 9 * (st.k + src.k) in
    if need > Float.Array.length st.data then begin
      let d = Float.Array.create (Int.max need (2 * Float.Array.length st.data)) in
      Float.Array.blit st.data 0 d 0 (9 * st.k);
      st.data <- d
    end;
    Float.Array.blit src.data 0 st.data (9 * st.k) (9 * src.k);
    st.k <- st.k + src.k
  end
let stored st = st.k

(* POV-Ray keeps a photon's flux in RGBE bytes (a shared exponent, each
   channel truncated to 8 bits of it) and its direction in two signed
   bytes of angle (127 steps a half turn): so here, for the same light *)
let rgbe v c =
  if v < 1e-32 then 0.
  else
    let _, e = Float.frexp v in
    Float.ldexp (Float.of_int (Float.to_int (Float.ldexp c (8 - e)))) (e - 8)

let byte_angle a = Float.of_int (Float.to_int (a *. 127. /. Float.pi)) *. Float.pi /. 127.

let add st x y z ~r ~g ~b dx dy dz =
  let v = Float.max r (Float.max g b) in
  let r = rgbe v r and g = rgbe v g and b = rgbe v b in
  let h = Float.sqrt ((dx *. dx) +. (dz *. dz)) in
  let theta = byte_angle (Float.asin (Float.max (-1.) (Float.min 1. dy))) in
  let phi = byte_angle (if h = 0. then 0. else Float.atan2 dz dx) in
  let dx = Float.cos theta *. Float.cos phi and dy = Float.sin theta and dz = Float.cos theta *. Float.sin phi in
  if 9 * (st.k + 1) > Float.Array.length st.data then begin
    let d = Float.Array.create (2 * Float.Array.length st.data) in
    Float.Array.blit st.data 0 d 0 (9 * st.k);
    st.data <- d
  end;
  let o = 9 * st.k in
  List.iteri (fun i v -> Float.Array.set st.data (o + i) v) [ x; y; z; r; g; b; dx; dy; dz ];
  st.k <- st.k + 1

let size m = m.n
let radius m = m.r0
let[@inline] position m i k = Float.Array.get m.pos ((3 * i) + k)
let[@inline] flux m i k = Float.Array.get m.col ((3 * i) + k)
let[@inline] direction m i k = Float.Array.get m.dir ((3 * i) + k)

(* The search state, per domain: the query point, normal and bound in
   a float array (a record mixing floats and ints would box them), the
   photons kept in a max-heap by distance. *)
type query = {
  q : Float.Array.t;
      (** x, y, z, nx, ny, nz, bound (squared), flatten (0 or 1), search
          radius; then the last gather's area and volume *)
  mutable heap_d : Float.Array.t;
  mutable heap_i : int array;
  mutable cnt : int;
  mutable cap : int;
  mutable over : bool;  (** a photon was dropped for a nearer one *)
}

let query_key =
  Scratch.key (fun () ->
      { q = Float.Array.make 11 0.; heap_d = Float.Array.create 0; heap_i = [||]; cnt = 0; cap = 0; over = false })

let query () = Scratch.get query_key
let[@inline] found q = q.cnt
let[@inline] area q = Float.Array.get q.q 9
let[@inline] volume q = Float.Array.get q.q 10
let[@inline] index q i = Array.unsafe_get q.heap_i i

(* Unchecked from here to the search: a photon's index is below [m.n],
   an axis 0 to 2, the query's fields are its 11, and the heap's entries
   below [cnt], at most [cap], its arrays' length (the search visits
   every photon near the query point; with the checks, photons.pov at
   160x120 ran 1,680 M instructions) *)
let fget = Float.Array.unsafe_get
let fset = Float.Array.unsafe_set

(* heap entries [a] and [b] exchanged *)
let swap q a b =
  let hd = q.heap_d and hi = q.heap_i in
  let td = fget hd a and ti = Array.unsafe_get hi a in
  fset hd a (fget hd b);
  Array.unsafe_set hi a (Array.unsafe_get hi b);
  fset hd b td;
  Array.unsafe_set hi b ti

let sift_down q =
  let hd = q.heap_d and n = q.cnt in
  let i = ref 0 and continue = ref true in
  while !continue do
    let l = (2 * !i) + 1 in
    if l >= n then continue := false
    else begin
      let r = l + 1 in
      let c = if r < n && fget hd r > fget hd l then r else l in
      if fget hd c > fget hd !i then begin
        swap q c !i;
        i := c
      end
      else continue := false
    end
  done

let sift_up q k =
  let hd = q.heap_d in
  let i = ref k in
  while !i > 0 && fget hd ((!i - 1) / 2) < fget hd !i do
    let p = (!i - 1) / 2 in
    swap q p !i;
    i := p
  done

(* photon [i] against the query: kept when nearer than the bound *)
let consider m qr i =
  let q = qr.q in
  let vx = fget m.pos (3 * i) -. fget q 0
  and vy = fget m.pos ((3 * i) + 1) -. fget q 1
  and vz = fget m.pos ((3 * i) + 2) -. fget q 2 in
  let d2 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
  let d2 =
    if fget q 7 > 0. then
      let nv = (vx *. fget q 3) +. (vy *. fget q 4) +. (vz *. fget q 5) in
      d2 *. (1. +. (16. *. Float.abs nv))
    else d2
  in
  if d2 < fget q 6 then begin
    if qr.cnt < qr.cap then begin
      fset qr.heap_d qr.cnt d2;
      Array.unsafe_set qr.heap_i qr.cnt i;
      qr.cnt <- qr.cnt + 1;
      sift_up qr (qr.cnt - 1);
      if qr.cnt = qr.cap then fset q 6 (fget qr.heap_d 0)
    end
    else begin
      qr.over <- true;
      fset qr.heap_d 0 d2;
      Array.unsafe_set qr.heap_i 0 i;
      sift_down qr;
      fset q 6 (fget qr.heap_d 0)
    end
  end

(* the node of range [lo, hi) is its middle photon; ints passed only *)
let rec search m qr lo hi =
  if lo < hi then begin
    let mid = (lo + hi) lsr 1 in
    let ax = Char.code (Bytes.unsafe_get m.axis mid) in
    let delta = fget qr.q ax -. fget m.pos ((3 * mid) + ax) in
    if delta < 0. then begin
      search m qr lo mid;
      if delta *. delta < fget qr.q 6 then search m qr (mid + 1) hi
    end
    else begin
      search m qr (mid + 1) hi;
      if delta *. delta < fget qr.q 6 then search m qr lo mid
    end;
    consider m qr mid
  end

(* the search radius in [q.(8)]: a float passed would be boxed *)
let reset m qr =
  let r = Float.Array.get qr.q 8 in
  (* at least one entry: [consider] writes the first when the heap is full *)
  let size = Int.max 1 m.gmax in
  if Float.Array.length qr.heap_d < size then begin
    qr.heap_d <- Float.Array.create size;
    qr.heap_i <- Array.make size 0
  end;
  qr.cap <- m.gmax;
  qr.cnt <- 0;
  qr.over <- false;
  Float.Array.set qr.q 6 (r *. r)

(* found within radius [r] (flattened when the query's flag says so);
   the area of the estimate *)
let run m qr =
  reset m qr;
  let r = Float.Array.get qr.q 8 in
  search m qr 0 m.n;
  let rr = if qr.over then Float.Array.get qr.heap_d 0 else r *. r in
  Float.Array.set qr.q 9 (Float.pi *. rr);
  Float.Array.set qr.q 10 (4. /. 3. *. Float.pi *. rr *. Float.sqrt rr)

let nearest m qr x y z ~radius =
  let q = qr.q in
  Float.Array.set q 0 x;
  Float.Array.set q 1 y;
  Float.Array.set q 2 z;
  Float.Array.set q 7 0.;
  Float.Array.set q 8 radius;
  run m qr;
  qr.cnt

(* POV-Ray's adaptive gather of the query set up *)
let adaptive m qr =
  Float.Array.set qr.q 8 m.r0;
  run m qr;
  if qr.cnt < m.gmin then begin
    (* POV-Ray's one expansion, to three times the radius: kept when the
       density barely changes, or when it holds only a few photons *)
    let n1 = qr.cnt and a1 = area qr in
    let prev = if n1 = 0 then 1e-16 else float_of_int n1 /. a1 in
    Float.Array.set qr.q 8 (3. *. m.r0);
    run m qr;
    let n2 = qr.cnt in
    let here = float_of_int n2 /. area qr in
    if not ((here -. prev) /. prev < m.tolerance || (n2 > 0 && n2 < m.emin)) then begin
      Float.Array.set qr.q 8 m.r0;
      run m qr;
      assert (qr.cnt = n1)
    end
  end

let gather m qr (p : Vec3.m) (n : Vec3.m) =
  let q = qr.q in
  Float.Array.set q 0 p.mx;
  Float.Array.set q 1 p.my;
  Float.Array.set q 2 p.mz;
  Float.Array.set q 3 n.mx;
  Float.Array.set q 4 n.my;
  Float.Array.set q 5 n.mz;
  Float.Array.set q 7 1.;
  adaptive m qr

let gather_volume m qr (p : Vec3.m) =
  let q = qr.q in
  Float.Array.set q 0 p.mx;
  Float.Array.set q 1 p.my;
  Float.Array.set q 2 p.mz;
  Float.Array.set q 7 0.;
  adaptive m qr

(* Building: quickselect the median of each range on its widest axis *)
let build ?(seed = 0) ?(volume = false) (s : settings) st =
  let n = st.k in
  let d = st.data in
  let idx = Array.init n Fun.id in
  let axis = Bytes.make (max n 1) '\000' in
  let coord i k = Float.Array.get d ((9 * i) + k) in
  let rec select lo hi k ax =
    (* the k-th smallest of idx[lo, hi) by axis [ax] at position k *)
    if hi - lo > 1 then begin
      let pivot = coord idx.((lo + hi) / 2) ax in
      let i = ref lo and j = ref (hi - 1) in
      while !i <= !j do
        while coord idx.(!i) ax < pivot do incr i done;
        while coord idx.(!j) ax > pivot do decr j done;
        if !i <= !j then begin
          let t = idx.(!i) in
          idx.(!i) <- idx.(!j);
          idx.(!j) <- t;
          incr i;
          decr j
        end
      done;
      if k <= !j then select lo (!j + 1) k ax else if k >= !i then select !i hi k ax
    end
  in
  let rec kd lo hi =
    if lo < hi then begin
      let lo3 = Array.make 3 infinity and hi3 = Array.make 3 neg_infinity in
      for j = lo to hi - 1 do
        for k = 0 to 2 do
          let c = coord idx.(j) k in
          if c < lo3.(k) then lo3.(k) <- c;
          if c > hi3.(k) then hi3.(k) <- c
        done
      done;
      let ext k = hi3.(k) -. lo3.(k) in
      let ax = if ext 0 >= ext 1 && ext 0 >= ext 2 then 0 else if ext 1 >= ext 2 then 1 else 2 in
      let mid = (lo + hi) lsr 1 in
      select lo hi mid ax;
      Bytes.set axis mid (Char.chr ax);
      kd lo mid;
      kd (mid + 1) hi
    end
  in
  kd 0 n;
  let part o = Float.Array.init (3 * n) (fun j -> Float.Array.get d ((9 * idx.(j / 3)) + o + (j mod 3))) in
  let m0 =
    { n; pos = part 0; col = part 3; dir = part 6; axis; r0 = 1.; gmin = s.gather_min; gmax = s.gather_max;
      tolerance = s.expand_tolerance; emin = s.expand_min }
  in
  let given = if volume then s.media_radius else s.radius in
  let r0 =
    if given > 0. then given
    else if n = 0 then 1.
    else begin
      (* POV-Ray's estimate: the density at the gather_max nearest photons
         of random photons, averaged; the radius holding gather_max at
         it, widened by the share well below the mean *)
      let rng = Random.State.make [| seed; n |] in
      let samples = max 100 (min 1000 (n / 20)) in
      let qr = query () in
      let density r cnt =
        if r <= 0. then 0.
        else if volume then 3. *. float_of_int cnt /. (4. *. Float.pi *. r *. r *. r)
        else float_of_int cnt /. (Float.pi *. r *. r)
      in
      let sum = ref 0. in
      for i = 1 to samples do
        let j = Random.State.int rng n in
        let cnt = nearest m0 qr (position m0 j 0) (position m0 j 1) (position m0 j 2) ~radius:1e7 in
        let r = if cnt < m0.gmax then 1e7 else Float.sqrt (Float.Array.get qr.heap_d 0) in
        let dn = if r = 0. then !sum /. float_of_int i else density r cnt in
        sum := !sum +. dn
      done;
      let avg = !sum /. float_of_int samples in
      let r =
        if volume then Float.pow (3. *. float_of_int m0.gmax /. (avg *. Float.pi *. 4.)) 0.3333
        else Float.sqrt (float_of_int m0.gmax /. (avg *. Float.pi))
      in
      let less = ref 0 in
      for _ = 1 to samples do
        let j = Random.State.int rng n in
        let cnt = nearest m0 qr (position m0 j 0) (position m0 j 1) (position m0 j 2) ~radius:r in
        let rr = if qr.over then Float.sqrt (Float.Array.get qr.heap_d 0) else r in
        let dn = density rr cnt in
        if dn > 0.05 *. avg && dn < 0.7 *. avg then incr less
      done;
      r *. (1. +. (20. *. float_of_int !less /. float_of_int samples))
    end
  in
  { m0 with r0 = (if volume then 2. *. r0 *. s.media_mult else r0 *. s.radius_mult) }
