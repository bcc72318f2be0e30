(* Per-domain scratch: the records a domain rewrites at every ray (the
   query's ray and hit, the traversal stack, the shading sums).

   Two things keep a domain's scratch from slowing the others.

   Lookup: [Domain.DLS.get] reads the domain's state array and compares
   with a sentinel that the standard library keeps in the heap; a profile
   of the snowman on 2 domains spent 30% of its time in DLS.get, 93% of
   that on the instruction waiting for those loads: a line shared with
   data another domain writes. A key here is an array indexed by
   [Domain.self_index] (below [max_domains], reused after a domain ends):
   one read of a line nobody writes once each domain has its slot.

   Placement: a record a domain writes must not share a cache line with
   data another domain reads, or every write takes the line from the
   other core. The scene is built by the main domain, and OCaml 5 puts the
   objects a domain promotes side by side in its own pools, one pool per
   size: the main domain's scratch, made at its first ray, used to land
   right after the scene's last records of the same size. [set_apart ()],
   called by the main domain before anything else is built, makes its
   scratch at once, between two layers of padding of every small size
   that stay alive for good. Other domains' scratch is in their own
   pools. Measured on the snowman, 800x600 rendered twice per domain: 2
   domains took 0.27 s, or 0.21 s with the scratch set apart (each domain
   rendering its own copy of the scene: 0.21 s; 1 domain: 0.41 s). *)

let max_domains = 128

type 'a key = { slots : 'a option array; make : unit -> 'a }

let makers : (unit -> unit) list ref = ref []

(* a domain's first [get] (or any, past [max_domains]): out of line, so
   that the copies of [get] inlined into the per-ray code are a load and
   a test (the snowman at 400x300, callgrind's cache model: instruction
   cache misses 2.79 M -> 1.62 M, Whitted.trace_ray 13.0 -> 11.2 KB) *)
let[@inline never] first k i =
  if i >= max_domains then k.make ()
  else begin
    let v = k.make () in
    k.slots.(i) <- Some v;
    v
  end

let get k =
  let i = Domain.self_index () in
  if i >= max_domains then first k i
  else match Array.unsafe_get k.slots i with Some v -> v | None -> first k i

let key make =
  let k = { slots = Array.make max_domains None; make } in
  makers := (fun () -> ignore (get k)) :: !makers;
  k

let padding : Obj.t list ref = ref []

(* 16 blocks of each size up to 32 words, and two of 300 (allocated
   outside the pools), promoted now *)
let pad () =
  for size = 1 to 32 do
    for _ = 1 to 16 do
      padding := Obj.repr (Array.make size 0) :: !padding
    done
  done;
  padding := Obj.repr (Array.make 300 0) :: Obj.repr (Array.make 300 0) :: !padding;
  Gc.minor ()

let set_apart () =
  pad ();
  List.iter (fun make -> make ()) !makers;
  Gc.minor ();
  pad ()

(* Records by nesting depth (a domain's frames of nested rays, of nested
   maps), made as deeper ones are first asked for *)
type 'a levels = { make_level : unit -> 'a; mutable items : 'a array; mutable depth : int }

let levels ?(initial = 4) make_level = { make_level; items = Array.init initial (fun _ -> make_level ()); depth = 0 }

let level l d =
  if d >= Array.length l.items then begin
    let old = l.items in
    l.items <- Array.init (2 * (d + 1)) (fun i -> if i < Array.length old then old.(i) else l.make_level ())
  end;
  Array.unsafe_get l.items d

let push l =
  let x = level l l.depth in
  l.depth <- l.depth + 1;
  x

let pop l = l.depth <- l.depth - 1
let reset l = l.depth <- 0
