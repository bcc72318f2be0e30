let sort_prefix a n =
  if n < 0 || n > Float.Array.length a then invalid_arg "Floats.sort_prefix";
  for i = 1 to n - 1 do
    let x = Float.Array.unsafe_get a i in
    let j = ref (i - 1) in
    while !j >= 0 && Float.Array.unsafe_get a !j > x do
      Float.Array.unsafe_set a (!j + 1) (Float.Array.unsafe_get a !j);
      decr j
    done;
    Float.Array.unsafe_set a (!j + 1) x
  done

let order_prefix a n (ord : int array) =
  if n < 0 || n > Float.Array.length a || n > Array.length ord then invalid_arg "Floats.order_prefix";
  for j = 0 to n - 1 do
    let x = Float.Array.unsafe_get a j in
    let i = ref j in
    while !i > 0 && Float.Array.unsafe_get a (Array.unsafe_get ord (!i - 1)) > x do
      Array.unsafe_set ord !i (Array.unsafe_get ord (!i - 1));
      decr i
    done;
    Array.unsafe_set ord !i j
  done

(* rounded to single precision (POV-Ray's SNGL fields, and floats read
   from files), kept as a double *)
let[@inline] single x = Int32.float_of_bits (Int32.bits_of_float x)

let[@inline] fmin (a : float) b = if a <= b then a else b
let[@inline] fmax (a : float) b = if a >= b then a else b
