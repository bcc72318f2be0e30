type error = Misuse of string | Bad_file of string

exception Stop of error

let misuse fmt = Printf.ksprintf (fun s -> raise (Stop (Misuse s))) fmt
let bad_file fmt = Printf.ksprintf (fun s -> raise (Stop (Bad_file s))) fmt

let switches =
  [
    ("+Wn", "image width (-W)");
    ("+Hn", "image height (-H)");
    ("+A[t], -A", "anti-aliasing on with threshold t (default 0.3), or off (--aa)");
    ("+AMn", "sampling method (only 1 is supported)");
    ("+Rn", "anti-aliasing depth (--aa-depth)");
    ("+J, -J", "jitter (camlray never jitters; accepted)");
    ("+Ofile", "output file (-o)");
    ("+Ifile", "input scene");
    ("+Ldir", "include folder (--include-path)");
    ("+WTn", "number of render threads (--domains)");
    ("+SRn +ERn +SCn +ECn", "start/end row/column, 1-based and inclusive, or fractions below 1 (--region)");
    ("+KFIn +KFFn", "initial/final frame of an animation (--frames)");
    ("+KIf +KFf, +Kf", "initial/final clock, or the clock of a single frame (--clock-range, --clock)");
    ("+SFn +EFn", "render only this subset of the animation's frames (--subset)");
    ("+D -D +P -P +V -V +GA -GA +FN +F", "display, pause, verbosity, messages, file type PNG: no effect");
  ]

(* "+W800" -> Some ("W", "800"); prefixes are matched longest first *)
let split_switch a =
  let body = String.sub a 1 (String.length a - 1) in
  let names =
    [ "KFI"; "KFF"; "KI"; "KF"; "SF"; "EF"; "AM"; "WT"; "SR"; "ER"; "SC"; "EC"; "GA"; "FN"; "W"; "H"; "A"; "R";
      "J"; "O"; "I"; "L"; "K"; "D"; "P"; "V"; "F"; "Q" ]
  in
  let upper = String.uppercase_ascii body in
  List.find_map
    (fun n ->
      let l = String.length n in
      if String.length upper >= l && String.sub upper 0 l = n then
        Some (n, String.sub body l (String.length body - l))
      else None)
    names

type region = { mutable sr : string option; mutable er : string option; mutable sc : string option; mutable ec : string option }
type aa = { mutable on : bool; mutable threshold : float option; mutable touched : bool }
type frames = {
  mutable kfi : string option;
  mutable kff : string option;
  mutable ki : string option;
  mutable kf : string option;
  mutable sf : string option;
  mutable ef : string option;
}

let num what v =
  match float_of_string_opt v with
  | Some f -> f
  | None -> misuse "%s needs a number, found %S" what v

let int_arg what v =
  match int_of_string_opt v with Some i -> i | None -> misuse "%s needs a whole number, found %S" what v

(* The options of one switch. *)
let of_switch ~warn ~region ~frames ~aa sign name value =
  let plus = sign = '+' in
  let need () = if value = "" then misuse "%c%s needs a value" sign name in
  match name with
  | "W" -> need (); [ "-W"; string_of_int (int_arg "+W" value) ]
  | "H" -> need (); [ "-H"; string_of_int (int_arg "+H" value) ]
  | "A" ->
      aa.touched <- true;
      aa.on <- plus;
      if plus && value <> "" then aa.threshold <- Some (num "+A" value);
      []
  | "AM" ->
      need ();
      if int_arg "+AM" value <> 1 then
        warn (Printf.sprintf "sampling method %s is not supported; camlray uses method 1" value);
      []
  | "R" -> need (); [ "--aa-depth"; string_of_int (int_arg "+R" value) ]
  | "J" -> []
  | "O" -> need (); [ "-o"; value ]
  | "I" -> need (); [ value ]
  | "L" -> need (); [ "--include-path"; value ]
  | "WT" -> need (); [ "--domains"; string_of_int (int_arg "+WT" value) ]
  | "SR" -> need (); region.sr <- Some value; []
  | "ER" -> need (); region.er <- Some value; []
  | "SC" -> need (); region.sc <- Some value; []
  | "EC" -> need (); region.ec <- Some value; []
  | "KFI" -> need (); frames.kfi <- Some value; []
  | "KFF" -> need (); frames.kff <- Some value; []
  | "KI" -> need (); frames.ki <- Some value; []
  | "KF" -> need (); frames.kf <- Some value; []
  | "SF" -> need (); frames.sf <- Some value; []
  | "EF" -> need (); frames.ef <- Some value; []
  | "K" -> need (); [ "--clock"; Printf.sprintf "%g" (num "+K" value) ]
  | "D" | "P" | "V" | "GA" | "Q" -> []
  | "FN" | "F" ->
      if value <> "" && value <> "8" && String.uppercase_ascii value <> "N" then
        warn (Printf.sprintf "output file type %c%s%s: camlray writes PNG (or PPM/PFM by extension)" sign name value);
      []
  | _ -> misuse "unknown POV-Ray switch %c%s%s" sign name value

(* Region switches -> --region X0,Y0,X1,Y1 (needs the size). POV-Ray's rows
   and columns are 1-based and inclusive, or fractions of the image when
   below 1. Resolved later by the driver, which knows the size: we pass
   them on as --pov-region SR,ER,SC,EC with empty fields for absent ones. *)
let region_opts r =
  if r.sr = None && r.er = None && r.sc = None && r.ec = None then []
  else
    let f = function None -> "" | Some v -> Printf.sprintf "%g" (num "+SR/+ER/+SC/+EC" v) in
    [ "--pov-region"; String.concat "," [ f r.sr; f r.er; f r.sc; f r.ec ] ]

let frame_opts fr =
  let fi = Option.map (int_arg "+KFI") fr.kfi and ff = Option.map (int_arg "+KFF") fr.kff in
  let frames =
    match (fi, ff) with
    | None, None -> []
    | _ ->
        let a = Option.value fi ~default:1 and b = Option.value ff ~default:1 in
        [ "--frames"; Printf.sprintf "%d..%d" a b ]
  in
  let clocks =
    match (fr.ki, fr.kf) with
    | None, None -> []
    | _ ->
        let a = Option.fold ~none:0. ~some:(num "+KI") fr.ki in
        let b = Option.fold ~none:1. ~some:(num "+KF") fr.kf in
        [ "--clock-range"; Printf.sprintf "%g..%g" a b ]
  in
  let subset =
    match (fr.sf, fr.ef) with
    | None, None -> []
    | _ ->
        let a = Option.fold ~none:min_int ~some:(int_arg "+SF") fr.sf in
        let b = Option.fold ~none:max_int ~some:(int_arg "+EF") fr.ef in
        [ "--subset"; Printf.sprintf "%d..%d" a b ]
  in
  frames @ clocks @ subset

(* ---------- INI files ---------- *)

let ini_bool v =
  match String.lowercase_ascii (String.trim v) with
  | "on" | "true" | "yes" | "1" -> true
  | "off" | "false" | "no" | "0" -> false
  | _ -> misuse "expected on or off, found %S" v

let ini_file ~warn ~region ~frames ~aa path =
  let text =
    try In_channel.with_open_bin path In_channel.input_all
    with Sys_error e -> bad_file "cannot read %s" e
  in
  let lines = String.split_on_char '\n' text in
  List.concat
    (List.mapi
       (fun i line ->
         let line = String.trim line in
         let line = match String.index_opt line ';' with Some j -> String.sub line 0 j | None -> line in
         let line = String.trim line in
         if line = "" || line.[0] = '[' then []
         else if line.[0] = '+' || line.[0] = '-' then
           match split_switch line with
           | Some (n, v) -> of_switch ~warn ~region ~frames ~aa line.[0] n v
           | None -> misuse "%s:%d: unknown switch %s" path (i + 1) line
         else
           match String.index_opt line '=' with
           | None -> misuse "%s:%d: expected KEY=VALUE, found %S" path (i + 1) line
           | Some j -> (
               let key = String.trim (String.sub line 0 j) in
               let v = String.trim (String.sub line (j + 1) (String.length line - j - 1)) in
               let v = if String.length v >= 2 && v.[0] = '"' && v.[String.length v - 1] = '"' then String.sub v 1 (String.length v - 2) else v in
               let at what = Printf.sprintf "%s:%d: %s" path (i + 1) what in
               match String.lowercase_ascii key with
               | "input_file_name" -> [ v ]
               | "output_file_name" -> [ "-o"; v ]
               | "width" -> [ "-W"; string_of_int (int_arg (at "Width") v) ]
               | "height" -> [ "-H"; string_of_int (int_arg (at "Height") v) ]
               | "antialias" -> aa.touched <- true; aa.on <- ini_bool v; []
               | "antialias_threshold" -> aa.threshold <- Some (num (at "Antialias_Threshold") v); []
               | "antialias_depth" -> [ "--aa-depth"; string_of_int (int_arg (at "Antialias_Depth") v) ]
               | "sampling_method" -> of_switch ~warn ~region ~frames ~aa '+' "AM" v
               | "jitter" | "jitter_amount" | "antialias_gamma" -> []
               | "library_path" -> [ "--include-path"; v ]
               | "work_threads" -> [ "--domains"; string_of_int (int_arg (at "Work_Threads") v) ]
               | "initial_frame" -> frames.kfi <- Some v; []
               | "final_frame" -> frames.kff <- Some v; []
               | "initial_clock" -> frames.ki <- Some v; []
               | "final_clock" -> frames.kf <- Some v; []
               | "subset_start_frame" -> frames.sf <- Some v; []
               | "subset_end_frame" -> frames.ef <- Some v; []
               | "clock" -> [ "--clock"; Printf.sprintf "%g" (num (at "Clock") v) ]
               | "start_row" -> region.sr <- Some v; []
               | "end_row" -> region.er <- Some v; []
               | "start_column" -> region.sc <- Some v; []
               | "end_column" -> region.ec <- Some v; []
               | "display" | "pause_when_done" | "verbose" | "output_to_file" | "output_file_type"
               | "output_alpha" | "bits_per_color" | "create_ini" | "debug_console"
               | "warning_console" | "render_console" | "statistic_console" | "all_console" ->
                   []
               | _ ->
                   warn (Printf.sprintf "%s:%d: unknown INI key %s (ignored)" path (i + 1) key);
                   []))
       lines)

let rewrite ~warn args =
  let region = { sr = None; er = None; sc = None; ec = None } in
  let frames = { kfi = None; kff = None; ki = None; kf = None; sf = None; ef = None } in
  let aa = { on = false; threshold = None; touched = false } in
  try
    let rest =
      List.concat_map
        (fun a ->
          let n = String.length a in
          if n >= 2 && a.[0] = '+' then
            match split_switch a with
            | Some (name, v) -> of_switch ~warn ~region ~frames ~aa a.[0] name v
            | None -> misuse "unknown POV-Ray switch %s" a
          else if List.mem a [ "-A"; "-J"; "-D"; "-P"; "-V"; "-GA"; "-F" ] then []
          else if Filename.check_suffix (String.lowercase_ascii a) ".ini" && Sys.file_exists a then
            ini_file ~warn ~region ~frames ~aa a
          else if Filename.check_suffix (String.lowercase_ascii a) ".ini" then
            bad_file "cannot read INI file %s: no such file" a
          else [ a ])
        args
    in
    let aa_opts =
      if aa.touched && aa.on then [ "--aa"; Printf.sprintf "%g" (Option.value aa.threshold ~default:0.3) ]
      else []
    in
    Ok (rest @ aa_opts @ region_opts region @ frame_opts frames)
  with Stop e -> Error e
