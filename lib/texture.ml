type layer = { pigment : Pigment.t; finish : Finish.t }
type t = layer list

let plain pigment finish = [ { pigment; finish } ]
let default = plain Pigment.black Finish.default
