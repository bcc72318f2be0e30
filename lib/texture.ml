type layer = {
  pigment : Pigment.t;
  normal : Normal.t option;
  finish : Finish.t;
  tmap : tmap option;
}

and tmap = { pattern : Pattern.t; entries : (float * t) array; xform : Transform.t }
and t = layer list

let layer pigment finish = { pigment; normal = None; finish; tmap = None }
let plain pigment finish = [ layer pigment finish ]
let default = plain Pigment.black Finish.default

let patterned pattern entries =
  { (layer Pigment.black Finish.default) with
    tmap = Some { pattern; entries; xform = Transform.identity } }

let blend m point =
  let v = Pattern.value m.pattern (Transform.inv_point m.xform point) in
  let n = Array.length m.entries in
  if n = 0 then [ (1., default) ]
  else if Pattern.is_block m.pattern.kind then
    [ (1., snd m.entries.(Int.max 0 (Int.min (n - 1) (int_of_float v)))) ]
  else
    let v0, t0 = m.entries.(0) in
    if v <= v0 then [ (1., t0) ]
    else
      let rec find i =
        if i >= n then [ (1., snd m.entries.(n - 1)) ]
        else
          let vi, ti = m.entries.(i) in
          if v < vi then
            let vp, tp = m.entries.(i - 1) in
            if vi -. vp <= 0. then [ (1., ti) ]
            else
              let k = (v -. vp) /. (vi -. vp) in
              [ (1. -. k, tp); (k, ti) ]
          else find (i + 1)
      in
      find 1

(* A layer that lets no light through makes the whole texture block it. *)
let blocks_light (t : t) =
  List.exists (fun l -> match l.tmap with None -> Pigment.opaque l.pigment | Some _ -> false) t

let rec transform_layer tr l =
  {
    l with
    pigment = Pigment.transform tr l.pigment;
    normal = Option.map (Normal.transform tr) l.normal;
    tmap =
      Option.map
        (fun m ->
          {
            m with
            xform = Transform.then_ m.xform tr;
            entries = Array.map (fun (v, t) -> (v, transform tr t)) m.entries;
          })
        l.tmap;
  }

and transform tr t = List.map (transform_layer tr) t
