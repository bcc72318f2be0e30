type t = Solid of Color.rgbft

let solid c = Solid c
let black = Solid (Color.opaque Color.black)
let eval p _point = match p with Solid c -> c
