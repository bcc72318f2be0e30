open Camlray

(* compiled objects, by the identity of their description *)
module Phys = Hashtbl.Make (struct
  type t = Sdl.obj

  let equal = ( == )
  let hash = Hashtbl.hash
end)

let compiled : Object.t option Phys.t = Phys.create 8
let reset () = Phys.reset compiled

let compile (o : Sdl.obj) =
  match Phys.find_opt compiled o with
  | Some c -> c
  | None ->
      let c = Compile.standalone o in
      Phys.replace compiled o c;
      c

(* POV-Ray's bound for what has none (BOUND_HUGE / 2) *)
let huge = 1e10

let extent _loc o ~max =
  let s = if max then huge else -.huge in
  match compile o with
  | None -> Vec3.make s s s
  | Some c -> (
      match Object.bounds c with
      | None -> Vec3.make s s s
      | Some (lo, hi) ->
          (* POV-Ray keeps a box as its lower corner and its size in single
             precision, and gives the upper corner as their sum *)
          let single = Camlray.Floats.single in
          let corner lo hi =
            let lo = Float.max (-.huge) (Float.min huge lo) and hi = Float.max (-.huge) (Float.min huge hi) in
            let l = single lo in
            (if max then l +. single (hi -. lo) else l) +. 0. (* no -0 *)
          in
          Vec3.make (corner lo.x hi.x) (corner lo.y hi.y) (corner lo.z hi.z))

let trace loc o start dir =
  if Vec3.length dir = 0. then Diag.error loc "trace: the direction is <0,0,0>";
  let missed = (Vec3.zero, Vec3.zero) in
  match compile o with
  | None -> missed
  | Some c ->
      let ray = Ray.make start (Vec3.normalize dir) in
      let h = Hit.create infinity and f = Object.found c in
      if Object.hit c ray Ray.epsilon h f then
        let p = Ray.at ray h.t in
        (p, Object.normal f.leaf p h)
      else missed

let inside _loc o p = match compile o with None -> false | Some c -> Object.inside c p

let object_pattern o =
  Pattern.Object
    (match compile o with Some c -> Object.inside_pattern c | None -> Pattern.inside (fun _ -> false))
