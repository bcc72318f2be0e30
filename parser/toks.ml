(* Tokens in chunks of 64: chunk c holds tokens 64c to 64c + 63. A
   released chunk is replaced by [||]. Small chunks are lexed just before
   they are parsed and die young: with chunks of 4096 every token outlived
   a minor collection, and 10^6 spheres took 15.8 s and 1.9 GB to check,
   against 11.4 s and 1.3 GB with 64 (256: 11.9 s, 1.5 GB). *)
let bits = 6
let size = 1 lsl bits
let margin = size

type memo = ..
type memo += Nothing

type t = {
  mutable chunks : Lexer.token array array;
  mutable memo : memo;  (** what a reader keeps about these tokens (see {!Fold}) *)
  mutable count : int;  (** tokens lexed so far *)
  lex : (unit -> Lexer.token) option;  (** [None]: a fixed sequence *)
  mutable finished : bool;
  mutable released : int;  (** chunks below this one are released *)
}

let of_array a =
  let n = Array.length a in
  let chunk c = Array.sub a (c * size) (min size (n - (c * size))) in
  let chunks = Array.init ((n + size - 1) / size) chunk in
  { chunks; memo = Nothing; count = n; lex = None; finished = true; released = 0 }

let of_text ~file text =
  { chunks = [||]; memo = Nothing; count = 0; lex = Some (Lexer.stream ~file text); finished = false; released = 0 }

(* lex one more chunk (or up to the end) *)
let fill t =
  match t.lex with
  | None -> t.finished <- true
  | Some next ->
      let c = t.count lsr bits in
      if c >= Array.length t.chunks then begin
        let grown = Array.make (max 16 (2 * Array.length t.chunks)) [||] in
        Array.blit t.chunks 0 grown 0 (Array.length t.chunks);
        t.chunks <- grown
      end;
      let first = next () in
      let chunk = Array.make size first in
      let k = ref 1 and eof = ref (first.raw = Lexer.Eof) in
      while (not !eof) && !k < size do
        let tok = next () in
        chunk.(!k) <- tok;
        incr k;
        if tok.raw = Lexer.Eof then eof := true
      done;
      t.chunks.(c) <- (if !k = size then chunk else Array.sub chunk 0 !k);
      t.count <- t.count + !k;
      if !eof then t.finished <- true

let rec mem t i = i >= 0 && (i < t.count || ((not t.finished) && (fill t; mem t i)))

(* a token not lexed yet, released, or past the end *)
let[@inline never] get_slow t i =
  if mem t i then begin
    let c = i lsr bits in
    if c < t.released then invalid_arg "Toks.get: a released token";
    Array.unsafe_get (Array.unsafe_get t.chunks c) (i land (size - 1))
  end
  else if i < 0 then invalid_arg "Toks.get: negative index"
  else
    (* past the end: the final Eof *)
    let c = (t.count - 1) lsr bits in
    let chunk = t.chunks.(c) in
    chunk.(Array.length chunk - 1)

let[@inline] lexed t i = i >= 0 && i < t.count && i lsr bits >= t.released

let[@inline] get t i =
  if lexed t i then
    Array.unsafe_get (Array.unsafe_get t.chunks (i lsr bits)) (i land (size - 1))
  else get_slow t i

let memo t = t.memo
let set_memo t m = t.memo <- m

let sub t pos len = Array.init len (fun k -> get t (pos + k))

let release t i =
  (* keep the chunk of i and the one before it *)
  let upto = (i lsr bits) - 1 in
  while t.released < upto do
    t.chunks.(t.released) <- [||];
    t.released <- t.released + 1
  done
