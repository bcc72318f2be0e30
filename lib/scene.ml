type settings = {
  max_trace_level : int;
  adc_bailout : float;
  ambient_light : Color.t;
  encoding : Image.encoding;
  legacy_alpha : bool;
}

type t = {
  objects : Object.t array;
  lights : Light.t array;
  camera : Camera.t;
  background : Color.t;
  sky : Sky.t;
  settings : settings;
}

let default_settings =
  {
    max_trace_level = 5;
    adc_bailout = 1. /. 255.;
    ambient_light = Color.white;
    encoding = Image.Srgb;
    legacy_alpha = false;
  }

type hit = { t : float; obj : Object.t; point : Vec3.t; normal : Vec3.t }

let intersect s r tmin tmax =
  let best = ref tmax and best_o = ref (-1) in
  Array.iteri
    (fun i o ->
      let t = Object.intersect o r tmin !best in
      if t < !best then (
        best := t;
        best_o := i))
    s.objects;
  if !best_o < 0 then None
  else
    let obj = s.objects.(!best_o) in
    let point = Ray.at r !best in
    Some { t = !best; obj; point; normal = Object.normal obj point }

(* Every crossing matters for coloured shadows, so walk all surfaces. *)
let occluders s (r : Ray.t) tmin tmax f =
  let n = Array.length s.objects in
  let rec objs i =
    if i >= n then true
    else
      let o = s.objects.(i) in
      if o.no_shadow then objs (i + 1) else crossings o tmin && objs (i + 1)
  and crossings o t0 =
    let t = Object.intersect o r t0 tmax in
    if t = infinity then true else f o t && crossings o (t +. Ray.epsilon)
  in
  objs 0
