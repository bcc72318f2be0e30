type layer = { pigment : Pigment.t; normal : Normal.t option; finish : Finish.t }
type t = layer list

let layer pigment finish = { pigment; normal = None; finish }
let plain pigment finish = [ layer pigment finish ]
let default = plain Pigment.black Finish.default

let transform_layer tr l =
  { l with pigment = Pigment.transform tr l.pigment; normal = Option.map (Normal.transform tr) l.normal }

let transform tr t = List.map (transform_layer tr) t
