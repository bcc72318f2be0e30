type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
  hollow : bool;
  caustics : float;
  media : Media.t list;
}

let default =
  { ior = 1.; fade_distance = 0.; fade_power = 0.; fade_color = Color.black; hollow = false; caustics = 0.; media = [] }

let[@inline] fade_channel i c d =
  if i.fade_distance = 0. then 1.
  else if i.fade_power >= 1000. then Float.exp (-.(1. -. c) *. d /. i.fade_distance)
  else c +. ((1. -. c) /. (1. +. Float.pow (d /. i.fade_distance) i.fade_power))

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

(* Lists of media entered, made once per domain: [inner :: media] for
   the last pairs met (a ray entering glass would otherwise make a list
   cell at every refraction) *)
let entered_size = 16

type entered = {
  inners : t array;
  outers : t list array;
  lists : t list array;
  mutable filled : int;
  mutable next : int;
}

let ring () =
  { inners = Array.make entered_size default; outers = Array.make entered_size [];
    lists = Array.make entered_size []; filled = 0; next = 0 }

let entered_key = Scratch.key ring

(* the same for the lists left: [media] without [inner] *)
let left_key = Scratch.key ring

let rec without inner = function [] -> [] | i :: r -> if i == inner then without inner r else i :: without inner r
let cons inner media = inner :: media

(* [make inner media] as kept in [e] for the pair, made and kept there
   when it is not ([make] a top-level function: no closure per call) *)
let memo e make inner media =
  let i = ref 0 in
  while !i < e.filled && not (Array.unsafe_get e.inners !i == inner && Array.unsafe_get e.outers !i == media) do
    incr i
  done;
  if !i < e.filled then Array.unsafe_get e.lists !i
  else begin
    let l = make inner media and k = e.next in
    e.inners.(k) <- inner;
    e.outers.(k) <- media;
    e.lists.(k) <- l;
    e.next <- (k + 1) mod entered_size;
    if e.filled < entered_size then e.filled <- e.filled + 1;
    l
  end

let leave inner media = memo (Scratch.get left_key) without inner media
let enter inner media = memo (Scratch.get entered_key) cons inner media

let beyond inner media =
  if not (List.memq inner media) then enter inner media
  else match media with i :: r when i == inner -> r | m -> leave inner m
