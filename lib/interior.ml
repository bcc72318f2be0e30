type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
  hollow : bool;
  caustics : float;
  media : Media.t list;
  mutable slot : int;
}

let default =
  { ior = 1.; fade_distance = 0.; fade_power = 0.; fade_color = Color.black; hollow = false; caustics = 0.; media = [];
    slot = 0 }

let[@inline] fade_channel i c d =
  if i.fade_distance = 0. then 1.
  else if i.fade_power >= 1000. then Float.exp (-.(1. -. c) *. d /. i.fade_distance)
  else c +. ((1. -. c) /. (1. +. Float.pow (d /. i.fade_distance) i.fade_power))

let copy i = { i with slot = i.slot }
let transform t i = if i.media = [] then i else { i with media = List.map (Media.transform t) i.media }

(* Shadow rays fade only with a fade_power (povray 3.7: fade_power 0 fades
   what the eye sees through, by 1/2, but not the light) *)
let fades_light i = i.fade_distance <> 0. && i.fade_power <> 0.

(* {2 The interiors a ray is inside} *)

(* Relative index of refraction across a surface of [inner] for a ray
   inside [media]: entering or leaving is decided as POV-Ray does, by
   whether the ray is already inside this interior, not by the side of
   the surface (the children of a CSG share their parent's interior, so in
   the overlap of a union of glass spheres the inner walls bend light as
   glass/air). [media] holds each interior once. *)
let rec ior_beyond inner = function
  | i :: r -> if i == inner then ior_beyond inner r else i.ior
  | [] -> 1.

(* no local function: so that it inlines, and its result is not boxed *)
let[@inline] relative_ior inner media =
  if not (List.memq inner media) then (match media with i :: _ -> i.ior | [] -> 1.) /. inner.ior
  else inner.ior /. ior_beyond inner media

(* The index ratio POV-Ray weighs a fresnel reflection by (its
   ComputeRelativeIOR), the inverse of [relative_ior] but for a ray
   leaving [inner] while inside other interiors too: there POV-Ray takes
   the innermost interior's index over [inner]'s, which is 1 when
   [inner] is the innermost (the ray leaves glass within a hollow sphere
   around the camera, say), and a fresnel surface then reflects nothing
   on the way out. *)
let[@inline] fresnel_ior inner media =
  match media with
  | [] -> inner.ior
  | i :: rest -> (
      if not (List.memq inner media) then inner.ior /. i.ior
      else match rest with [] -> 1. /. inner.ior | _ :: _ -> i.ior /. inner.ior)

(* Lists of media entered, made once per domain: [inner :: media] for
   the pairs met (a ray entering glass would otherwise make a list cell
   at every refraction). A pair is looked up by a hash, in one set of
   [ways] pairs out of [sets]; a full set replaces its pairs in turn.
   Hashing lets the cache hold many pairs (a scene with dozens of glass
   objects meets hundreds), where a list searched whole held 16: 4.8
   words a camera ray on POV-Ray's stackertransp.pov, 0.9 on glass.pov.
   The hash is of the interiors' [slot]s, numbers given as a scene is
   made (an interior's address moves with the collector, and the many
   glass boxes of stackertransp.pov have the same fields). *)
let sets = 256
let ways = 4

type entered = {
  inners : t array;
  outers : t list array;
  lists : t list array;
  next : Bytes.t; (* per set: the way replaced next *)
}

(* what an empty slot holds: no interior a ray meets is this one *)
let vacant = { default with ior = Float.nan }

let ring () =
  let n = sets * ways in
  { inners = Array.make n vacant; outers = Array.make n []; lists = Array.make n []; next = Bytes.make sets '\000' }

let entered_key = Scratch.key ring

(* the same for the lists left: [media] without [inner] *)
let left_key = Scratch.key ring

let rec without inner = function [] -> [] | i :: r -> if i == inner then without inner r else i :: without inner r
let cons inner media = inner :: media

(* the set of the pair: by the interiors' slots (at most four of the
   list's) *)
let set_of inner media =
  let rec go h k = function
    | (i : t) :: r when k < 4 -> go ((h * 31) + i.slot) (k + 1) r
    | _ -> h
  in
  go (inner.slot * 7) 0 media land (sets - 1)

let numbered = Atomic.make 0
(* [default], shared by every object without an interior and copied by
   the parser into every interior it reads, keeps slot 0: a scene made
   must not change what later parses build (interiors are compared
   whole) *)
let number i = if i != default then i.slot <- Atomic.fetch_and_add numbered 1

(* the same interiors in the same order (a list left is made afresh,
   and equals one kept) *)
let rec same a b = a == b || match (a, b) with x :: r, y :: s -> x == y && same r s | _ -> false

(* [make inner media] as kept in [e] for the pair, made and kept there
   when it is not ([make] a top-level function: no closure per call) *)
let memo e make inner media =
  let base = ways * set_of inner media in
  let i = ref 0 in
  while
    !i < ways && not (Array.unsafe_get e.inners (base + !i) == inner && same (Array.unsafe_get e.outers (base + !i)) media)
  do
    incr i
  done;
  if !i < ways then Array.unsafe_get e.lists (base + !i)
  else begin
    let l = make inner media in
    let set = base / ways in
    let w = Char.code (Bytes.unsafe_get e.next set) in
    let k = base + w in
    e.inners.(k) <- inner;
    e.outers.(k) <- media;
    e.lists.(k) <- l;
    Bytes.unsafe_set e.next set (Char.unsafe_chr ((w + 1) mod ways));
    l
  end

let leave inner media = memo (Scratch.get left_key) without inner media
let enter inner media = memo (Scratch.get entered_key) cons inner media

let beyond inner media =
  if not (List.memq inner media) then enter inner media
  else match media with i :: r when i == inner -> r | m -> leave inner m
