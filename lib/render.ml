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
   a larger minor heap in every rendering domain (Gc.set acts on the
   calling domain only) makes the stops rare; the calling domain gets its
   own size back afterwards. One domain never waits for another: it keeps
   its heap. With more domains than cores, 16 MB (RTIOW in mc mode on 4
   domains, 2 cores: 1.05 s with 8 MB, 0.87 s with 16 MB; the snowman was
   slower with 64 or 256 MB).
   Whatever the size, each rendering domain has a minor collection at its
   first tile (growing the heap makes one; a heap already large enough
   gets [Gc.minor]): until then, what the domain allocated as it started
   stays packed in its minor heap, and the rendering code itself runs
   slower on every domain (time in loads of scene data and in stores to
   scratch, not in the collector: cache lines shared between domains, it
   seems). Measured on 2 cores, snowman 1600x1200 on 2 domains: every
   domain started on 16 MB heaps (OCAMLRUNPARAM=s=2M, so no growing) 0.33
   to 0.35 s, the same with [Gc.minor] at each first tile 0.23 to 0.24 s,
   as camlray runs by default (0.25); a [Gc.minor] in the main domain
   before the pool starts does not help. The size matters little there:
   regrowing by one page or to 8 MB, 0.234 and 0.239 s (medians of 10
   alternated runs); RTIOW in mc mode, 650 collections of 2 MB heaps,
   0.844 s against 0.850 s with 8 MB. 8 MB is kept: where more cores wait
   at each stop, fewer stops count more. *)
let minor_words domains =
  if domains > Domain.recommended_domain_count () then 2 * 1024 * 1024 (* 16 MB *)
  else 1024 * 1024 (* 8 MB per domain *)

let big_minor = Domain.DLS.new_key (fun () -> false)

let ensure_minor_heap words =
  if not (Domain.DLS.get big_minor) then begin
    Domain.DLS.set big_minor true;
    let g = Gc.get () in
    if g.minor_heap_size < words then Gc.set { g with minor_heap_size = words } else Gc.minor ()
  end

(* Tasks of up to 4 tiles: each task of [parallel_for] costs a few
   microseconds, a 16x16 tile of the snowman some 60 (2 domains, snowman
   1600x1200: 0.263 s with one tile per task, 0.255 s with 4; 5 alternated
   runs, medians), and at least 32 tasks per domain keep them balanced. *)
let chunk ~domains n = Int.max 1 (Int.min 4 (n / (32 * domains)))

let parallel ~domains n f =
  if domains <= 1 || n <= 1 then
    for i = 0 to n - 1 do
      f i
    done
  else
    let pool = T.setup_pool ~num_domains:(min n domains - 1) () in
    Fun.protect
      ~finally:(fun () -> T.teardown_pool pool)
      (fun () -> T.run pool (fun () -> T.parallel_for pool ~chunk_size:(chunk ~domains n) ~start:0 ~finish:(n - 1) ~body:f))

let run_tiles ~domains ?(progress = fun ~done_:_ ~total:_ -> ())
    ?(cancelled = fun () -> false) ?order_seed ~width ~height ~size f =
  let ts = tiles ~width ~height ~size in
  Option.iter (fun seed -> shuffle seed ts) order_seed;
  let total = Array.length ts in
  let finished = Atomic.make 0 in
  let report = Mutex.create () in
  let stop = Atomic.make false in
  let body i =
    if domains > 1 then ensure_minor_heap (minor_words domains);
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
  let own = (Gc.get ()).minor_heap_size and was_big = Domain.DLS.get big_minor in
  let restore () =
    if not was_big then begin
      Domain.DLS.set big_minor false;
      let g = Gc.get () in
      if g.minor_heap_size <> own then Gc.set { g with minor_heap_size = own }
    end
  in
  Fun.protect ~finally:restore (fun () -> parallel ~domains total body);
  if Atomic.get stop then raise Cancelled

(* the sum a pixel function writes into, per domain *)
let pixel_key = Scratch.key (fun () -> Color.acc 0.)

let image_into ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f =
  let r = match region with Some r -> r | None -> { x0 = 0; y0 = 0; x1 = width; y1 = height } in
  if r.x0 < 0 || r.y0 < 0 || r.x1 > width || r.y1 > height || r.x0 >= r.x1 || r.y0 >= r.y1 then
    invalid_arg "Render.image: region outside the image";
  let img = Image.create_unset (r.x1 - r.x0) (r.y1 - r.y0) in
  let cancelled = Option.value cancelled ~default:(fun () -> false) in
  run_tiles ~domains ?progress ~cancelled ?order_seed ~width ~height ~size:16 (fun t ->
      let c = Scratch.get pixel_key in
      for y = Int.max t.y0 r.y0 to Int.min t.y1 r.y1 - 1 do
        for x = Int.max t.x0 r.x0 to Int.min t.x1 r.x1 - 1 do
          (* a pixel can take long (mc, many samples): stop between pixels *)
          if cancelled () then raise Cancelled;
          f x y c;
          Image.set img (x - r.x0) (y - r.y0) c.ar c.ag c.ab
        done
      done);
  img

let image ~domains ?progress ?cancelled ?order_seed ?region ~width ~height f =
  image_into ~domains ?progress ?cancelled ?order_seed ?region ~width ~height (fun x y out ->
      let c : Color.t = f x y in
      Color.acc_set out c.r c.g c.b)
