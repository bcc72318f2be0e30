type t = { pigments : Pigment.t list }

let none = { pigments = [] }
let is_empty s = s.pigments = []
let transform tr s = { pigments = List.map (Pigment.transform tr) s.pigments }

let eval s ~background dir =
  let rec go acc w = function
    | [] -> Color.add acc (Color.mul w background)
    | p :: rest ->
        let c = Pigment.eval p dir in
        let alpha = 1. -. c.filter -. c.transmit in
        let acc = Color.add acc (Color.scale alpha (Color.mul w c.c)) in
        let w = Color.mul w (Color.add (Color.scale c.filter c.c) (Color.gray c.transmit)) in
        if Color.is_black w then acc else go acc w rest
  in
  go Color.black Color.white s.pigments
