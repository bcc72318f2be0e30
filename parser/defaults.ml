open Camlray

let version_ = ref 3.62
let given = ref false
let first = ref None
let items_seen = ref false
let tex = ref (Texture.layer Pigment.black Finish.default)
let tex_set = ref false
let charset_ = ref `Ascii
let warned : (string, unit) Hashtbl.t = Hashtbl.create 4

let reset () =
  version_ := 3.62;
  given := false;
  first := None;
  items_seen := false;
  tex := Texture.layer Pigment.black Finish.default;
  tex_set := false;
  charset_ := `Ascii;
  Hashtbl.reset warned

let version () = !version_
let charset () = !charset_
let set_charset c = charset_ := c

let set_version v =
  version_ := v;
  given := true;
  if (not !items_seen) && !first = None then first := Some v

let restore_version v = version_ := v
let version_given () = !given
let first_version () = !first
let mark_item () = items_seen := true
let texture () = !tex
let texture_set () = !tex_set
let set_finish f = tex_set := true; tex := { !tex with finish = f }
let set_pigment p = tex_set := true; tex := { !tex with pigment = p }
let set_normal n = tex_set := true; tex := { !tex with normal = n }

let finder : (Loc.t -> string -> string option) ref = ref (fun _ _ -> None)
let set_finder f = finder := f
let find_file loc name = !finder loc name

let warn_once key loc msg =
  if not (Hashtbl.mem warned key) then begin
    Hashtbl.replace warned key ();
    Diag.warning loc msg
  end
