module T = Domainslib.Task

type tile = { x0 : int; y0 : int; x1 : int; y1 : int }

exception Cancelled

let tiles ~width ~height ~size =
  let nx = (width + size - 1) / size and ny = (height + size - 1) / size in
  Array.init (nx * ny) (fun i ->
      let tx = i mod nx and ty = i / nx in
      {
        x0 = tx * size;
        y0 = ty * size;
        x1 = min width ((tx + 1) * size);
        y1 = min height ((ty + 1) * size);
      })

let shuffle seed a =
  let st = Random.State.make [| seed |] in
  for i = Array.length a - 1 downto 1 do
    let j = Random.State.int st (i + 1) in
    let x = a.(i) in
    a.(i) <- a.(j);
    a.(j) <- x
  done

(* Every minor collection stops all domains at once, and with more
   domains than cores a descheduled domain holds the others at each one:
   a domain that allocates gets a larger minor heap (Gc.set acts on the
   calling domain only), which makes the stops rare; the calling domain
   gets its own size back afterwards. With more domains than cores, 16 MB
   (RTIOW in mc mode on 4 domains, 2 cores, when its samples allocated:
   1.05 s with 8 MB, 0.87 s with 16 MB; the snowman was slower with 64 or
   256 MB), 8 MB otherwise.
   Only a domain that allocates: growing the heap is itself a collection,
   a stop of all domains, and shading that allocates nothing (whitted
   camera rays, Monte Carlo samples, in the common case) never fills even
   the default heap. A domain's allocation is watched from its second tile
   (the first makes its scratch) and the heap grown once it passes 1 K
   words a tile on average (4 a pixel; the Cornell box's area light, some
   1,000 words a camera ray, passes it at once; the snowman, 0.1 words a
   camera ray and its tiles' records, never). Measured on 2 cores, 1600x1200, medians
   of 5 to 7 alternated runs, growing at the first tile against growing
   only when allocating: snowman on 4 domains 0.229 against 0.210 s (2
   domains 0.203 both), default scene 0.384 against 0.360 s (0.342 and
   0.339); the Cornell box (400x400) on 4 domains needs its heap grown:
   0.401 s, against 0.697 s never grown.
   (A collection at each domain's first tile used to matter on its own:
   what a domain allocated as it started stayed packed in its minor heap
   and the snowman on 2 domains took 0.33 s instead of 0.23 s; no longer
   measurable since per-domain scratch went through [Scratch]: 0.203 s
   with or without it.) *)
let minor_words domains =
  if domains > Domain.recommended_domain_count () then 2 * 1024 * 1024 (* 16 MB *)
  else 1024 * 1024 (* 8 MB per domain *)

(* words a tile may allocate, on average, without the heap growing *)
let per_tile = 1024.

(* per domain: tiles started, its minor words at its second (the first
   makes the domain's scratch), whether its heap grew *)
type watch = { mutable tiles : int; mutable grown : bool; from : Float.Array.t }

let watch_key = Domain.DLS.new_key (fun () -> { tiles = 0; grown = false; from = Float.Array.make 1 0. })

let watch_allocation words =
  let w = Domain.DLS.get watch_key in
  if not w.grown then begin
    let now = Gc.minor_words () in
    w.tiles <- w.tiles + 1;
    if w.tiles = 2 then Float.Array.unsafe_set w.from 0 now
    else if w.tiles > 3 && now -. Float.Array.unsafe_get w.from 0 > per_tile *. float_of_int (w.tiles - 2) then begin
      w.grown <- true;
      let g = Gc.get () in
      if g.minor_heap_size < words then Gc.set { g with minor_heap_size = words }
    end
  end

(* Tasks of up to 4 tiles, and at least 96 tasks per domain: each task
   of [parallel_for] costs a few microseconds, a 16x16 tile of the snowman
   some 25 to 60, and the last tasks decide when the render ends. A large
   whitted image has many cheap tiles: 4 a task (default scene 1600x1200
   on 2 domains, 7,500 tiles: 0.322 s with 4, 0.346 s with 1; medians of 5
   alternated runs). A Monte Carlo image has fewer, dearer ones: RTIOW
   400x225 at 16 spp, 375 tiles of some 3.5 ms, on 4 domains 0.686 s with
   2 a task (the rule of 32 tasks a domain), 0.699 s with 4, 0.667 s with
   1, as fast as on 2 domains (0.668 s). *)
let chunk ~domains n = Int.max 1 (Int.min 4 (n / (96 * domains)))

(* The pool of the command being run, set by [with_pool] (read and set by
   the main domain only), and the parallel regions started so far. A
   worker that has finished a region sleeps in domainslib's channel, and
   waking it costs the next region its first tiles: the render's first
   tile on the second domain began 0.9 to 2.9 ms after the first domain's
   (median 1.0 ms, snowman at 800x600, 12 runs), 0.06 to 0.4 ms with the
   worker kept spinning (median 0.2 ms); a pool per region also cost 0.2
   to 0.4 ms to set up and 0.3 to 1.8 ms to tear down, three times a
   render on 2 domains (the trace and the PNG's two passes). So a command
   sets up one pool, and after each region its workers spin until the
   next region starts or [linger_s] has passed, as OpenMP runtimes do
   (not with more domains than cores, where a spinning worker would take
   a core from one with work). *)
(* With more domains than cores the pool is set up at the first parallel
   loop instead, after the parse: a minor collection stops every domain,
   and a pool's sleeping workers each have to be woken for it, with only
   the one free core to run on. The 10^5-triangle mesh (1600x1200, 2
   cores) parses in 0.091 s on 1 domain and 0.090 s on 2, but 0.124 to
   0.143 s with 4 domains' pool waiting (217 minor collections). *)
type shared = { domains : int; mutable pool : T.pool option }

let current : shared option ref = ref None

let regions = Atomic.make 0
let linger_s = 0.05

let lingers domains = domains <= Domain.recommended_domain_count ()

let linger pool workers =
  let g = Atomic.get regions in
  let spin () =
    let deadline = Unix.gettimeofday () +. linger_s in
    (* the clock read once in 1024 turns *)
    let k = ref 0 in
    while Atomic.get regions = g && (!k land 1023 <> 0 || Unix.gettimeofday () < deadline) do
      incr k;
      Domain.cpu_relax ()
    done
  in
  for _ = 1 to workers do
    ignore (T.async pool spin)
  done

(* the command's pool, set up at its first use *)
let pool_of shared =
  match shared.pool with
  | Some p -> p
  | None ->
      let p = T.setup_pool ~num_domains:(shared.domains - 1) () in
      if lingers shared.domains then linger p (shared.domains - 1);
      shared.pool <- Some p;
      p

let with_pool ~domains f =
  match !current with
  | Some _ -> f ()
  | None when domains <= 1 || not (Domain.is_main_domain ()) -> f ()
  | None ->
      let shared = { domains; pool = None } in
      if lingers domains then ignore (pool_of shared);
      current := Some shared;
      Fun.protect
        ~finally:(fun () ->
          current := None;
          Atomic.incr regions;
          Option.iter T.teardown_pool shared.pool)
        f

let parallel ~domains n f =
  if domains <= 1 || n <= 1 then
    for i = 0 to n - 1 do
      f i
    done
  else
    let run pool = T.run pool (fun () -> T.parallel_for pool ~chunk_size:(chunk ~domains n) ~start:0 ~finish:(n - 1) ~body:f) in
    match !current with
    | Some ({ domains = d; _ } as s) when d = domains && Domain.is_main_domain () ->
        let pool = pool_of s in
        Atomic.incr regions;
        run pool;
        if lingers domains then linger pool (domains - 1)
    | _ ->
        let pool = T.setup_pool ~num_domains:(min n domains - 1) () in
        Fun.protect ~finally:(fun () -> T.teardown_pool pool) (fun () -> run pool)

(* One task per domain, each taking indices from a counter. Radiosity's
   final pass on radiosity2.pov at 320x240, 2 domains (76,800 samples of
   some 7 us in batches of up to 128): traced ahead in 0.35 s with
   [parallel] (a task, and its fibre's stack grown, per sample), 0.25 s
   this way. *)
let pulled ~domains n f =
  if domains <= 1 || n <= 1 then
    for i = 0 to n - 1 do
      f i
    done
  else begin
    let next = Atomic.make 0 in
    parallel ~domains (Int.min domains n) (fun _ ->
        let i = ref (Atomic.fetch_and_add next 1) in
        while !i < n do
          f !i;
          i := Atomic.fetch_and_add next 1
        done)
  end

let run_tiles ~domains ?(progress = fun ~done_:_ ~total:_ -> ())
    ?(cancelled = fun () -> false) ?order_seed ~width ~height ~size f =
  let ts = tiles ~width ~height ~size in
  Option.iter (fun seed -> shuffle seed ts) order_seed;
  let total = Array.length ts in
  let finished = Atomic.make 0 in
  let report = Mutex.create () in
  let stop = Atomic.make false in
  let body i =
    if domains > 1 then watch_allocation (minor_words domains);
    if Atomic.get stop || cancelled () then Atomic.set stop true
    else begin
      f ts.(i);
      let d = 1 + Atomic.fetch_and_add finished 1 in
      (* no closure per tile *)
      if Mutex.try_lock report then begin
        match progress ~done_:d ~total with
        | () -> Mutex.unlock report
        | exception e ->
            Mutex.unlock report;
            raise e
      end
    end
  in
  let own = (Gc.get ()).minor_heap_size and w = Domain.DLS.get watch_key in
  let was_grown = w.grown in
  if not was_grown then w.tiles <- 0;
  let restore () =
    if not was_grown then begin
      w.grown <- false;
      w.tiles <- 0;
      let g = Gc.get () in
      if g.minor_heap_size <> own then Gc.set { g with minor_heap_size = own }
    end
  in
  Fun.protect ~finally:restore (fun () -> parallel ~domains total body);
  if Atomic.get stop then raise Cancelled

(* the sum a pixel function writes into, per domain *)
let pixel_key = Scratch.key (fun () -> Color.acc 0.)

(* The pixels of [region] (default: the whole image), each stored by
   [store] at its place in the region. *)
let pixels ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f ~frame ~store =
  let r = match region with Some r -> r | None -> { x0 = 0; y0 = 0; x1 = width; y1 = height } in
  if r.x0 < 0 || r.y0 < 0 || r.x1 > width || r.y1 > height || r.x0 >= r.x1 || r.y0 >= r.y1 then
    invalid_arg "Render.image: region outside the image";
  let img = frame (r.x1 - r.x0) (r.y1 - r.y0) in
  let cancelled = Option.value cancelled ~default:(fun () -> false) in
  run_tiles ~domains ?progress ~cancelled ?order_seed ~width ~height ~size:16 (fun t ->
      let c = Scratch.get pixel_key in
      for y = Int.max t.y0 r.y0 to Int.min t.y1 r.y1 - 1 do
        for x = Int.max t.x0 r.x0 to Int.min t.x1 r.x1 - 1 do
          (* a pixel can take long (mc, many samples): stop between pixels *)
          if cancelled () then raise Cancelled;
          f x y c;
          store img (x - r.x0) (y - r.y0) c
        done
      done);
  img

let image_into ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f =
  pixels ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f ~frame:Image.create_unset
    ~store:(fun img x y (c : Color.acc) -> Image.set img x y c.ar c.ag c.ab)

let rgb8_into ~domains ?progress ?cancelled ?order_seed ?region ~width ~height encoding f =
  let q = Image.quantizer encoding in
  pixels ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f ~frame:Image.create_rgb8
    ~store:(fun img x y (c : Color.acc) -> Image.set_rgb8 q img x y c.ar c.ag c.ab)

let image ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f =
  image_into ~domains ?progress ?cancelled ?order_seed ?region ~width ~height (fun x y out ->
      let c : Color.t = f x y in
      Color.acc_set out c.r c.g c.b)
