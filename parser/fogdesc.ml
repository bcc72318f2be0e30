open Camlray

type t = {
  kind : int;
  distance : float;
  color : Color.rgbft;
  offset : float;
  alt : float;
  up : Vec3.t;
  turb : Vec3.t option;
  depth : float;
  octaves : int;
  omega : float;
  lambda : float;
  xf : Transform.t;
}

let empty =
  { kind = 1; distance = 0.; color = Color.rgbft 0. 0. 0. 0. 0.; offset = 0.; alt = 0.; up = Vec3.unit_y;
    turb = None; depth = 0.5; octaves = 6; omega = 0.5; lambda = 2.; xf = Transform.identity }

type item = t -> t

let value loc v d =
  match v with
  | Value.Float x -> { d with distance = x }
  | v -> { d with color = Value.to_color loc v }

let distance x d = { d with distance = x }
let color c d = { d with color = c }

let kind loc k d =
  if k <> 1 && k <> 2 then Diag.error loc "fog_type is 1 (constant fog) or 2 (ground fog), found %d" k;
  { d with kind = k }

let offset x d = { d with offset = x }
let alt x d = { d with alt = x }
let up v d = { d with up = v }
let turbulence v d = { d with turb = Some v }
(* POV-Ray keeps turb_depth, omega and lambda in single precision *)
let turb_depth x d = { d with depth = Floats.single x }

(* POV-Ray keeps octaves within 1 to 10 *)
let octaves _loc n d = { d with octaves = max 1 (min 10 n) }

let omega x d = { d with omega = Floats.single x }
let lambda x d = { d with lambda = Floats.single x }
let transform t d = { d with xf = Transform.then_ d.xf t }

let fog loc d : Fog.t =
  let turbulence =
    Option.map
      (fun amount -> { Fog.amount; depth = d.depth; octaves = d.octaves; omega = d.omega; lambda = d.lambda })
      d.turb
  in
  let kind =
    if d.kind = 1 then Fog.Constant
    else begin
      if not (d.alt > 0.) then Diag.error loc "a ground fog (fog_type 2) needs fog_alt > 0, found %g" d.alt;
      let up = Transform.vector d.xf d.up in
      if Vec3.length up = 0. then Diag.error loc "a fog's up vector cannot be zero";
      Fog.Ground { offset = d.offset; alt = d.alt; up = Vec3.normalize up }
    end
  in
  { Fog.kind; distance = d.distance; color = d.color; turbulence }
