open Camlray

let version_ = ref 3.62
let given = ref false
let first = ref None
let items_seen = ref false
let tex = ref (Texture.layer Pigment.black Finish.default)
let tex_set = ref false
let template : Normal.t option ref = ref None
let charset_ = ref `Ascii
let noise_explicit = ref false
let warned : (string, unit) Hashtbl.t = Hashtbl.create 4

let reset () =
  version_ := 3.62;
  given := false;
  first := None;
  items_seen := false;
  tex := Texture.layer Pigment.black Finish.default;
  tex_set := false;
  template := None;
  charset_ := `Ascii;
  noise_explicit := false;
  Pattern.scene_noise_generator := 2;
  Value.working_gamma := 1.;
  Hashtbl.reset warned

let version () = !version_
let charset () = !charset_
let set_charset c = charset_ := c

(* POV-Ray's scene noise generator follows each #version until
   global_settings name one: 1 (the original noise) below 3.5, else 2 *)
let noise_for_version v = if v < 3.5 then 1 else 2

let set_version v =
  version_ := v;
  given := true;
  if not !noise_explicit then Pattern.scene_noise_generator := noise_for_version v;
  if (not !items_seen) && !first = None then first := Some v

let set_noise_generator n =
  noise_explicit := true;
  Pattern.scene_noise_generator := n

let restore_version v = version_ := v
let version_given () = !given
let first_version () = !first
let mark_item () = items_seen := true
let texture () = !tex
let texture_set () = !tex_set
let set_finish f = tex_set := true; tex := { !tex with finish = f }
let set_pigment p = tex_set := true; tex := { !tex with pigment = p }
let set_normal n = tex_set := true; tex := { !tex with normal = n }
let normal_template () = !template
let set_normal_template n = template := n

let finder : (Loc.t -> string -> string option) ref = ref (fun _ _ -> None)
let set_finder f = finder := f
let find_file loc name = !finder loc name

let warn_once key loc msg =
  if not (Hashtbl.mem warned key) then begin
    Hashtbl.replace warned key ();
    Diag.warning loc msg
  end
