exception Bad of int * string

type group = {
  name : string;
  mutable faces : (int * int) array list;  (* (vertex, normal or -1) per corner, reversed *)
}

let ident s =
  let b = Buffer.create (String.length s) in
  String.iter (fun c -> match c with
      | 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' -> Buffer.add_char b c
      | _ -> Buffer.add_char b '_') s;
  "OBJ_" ^ Buffer.contents b

let parse path text =
  let verts = ref [] and nv = ref 0 and norms = ref [] and nn = ref 0 in
  let base = Filename.remove_extension (Filename.basename path) in
  let groups = ref [] in
  let current = ref None in
  let group name = let g = { name; faces = [] } in groups := g :: !groups; current := Some g; g in
  let lines = String.split_on_char '\n' text in
  List.iteri (fun i line ->
      let ln = i + 1 in
      let line = match String.index_opt line '#' with Some k -> String.sub line 0 k | None -> line in
      let words = List.filter (( <> ) "") (String.split_on_char ' ' (String.map (function '\t' | '\r' -> ' ' | c -> c) line)) in
      let num w = match float_of_string_opt w with
        | Some f when Float.is_finite f -> f
        | _ -> raise (Bad (ln, Printf.sprintf "%S is not a number" w)) in
      let vec = function
        | x :: y :: z :: _ -> (num x, num y, num z)
        | _ -> raise (Bad (ln, "expected three coordinates")) in
      let index n count w =
        match int_of_string_opt w with
        | Some k when k > 0 && k <= count -> k - 1
        | Some k when k < 0 && -k <= count -> count + k
        | _ -> raise (Bad (ln, Printf.sprintf "%s index %S out of range (1..%d)" n w count)) in
      match words with
      | "v" :: r -> verts := vec r :: !verts; incr nv
      | "vn" :: r -> norms := vec r :: !norms; incr nn
      | ("g" | "o") :: names -> ignore (group (if names = [] then base ^ "_default" else String.concat "_" names))
      | "f" :: corners ->
          if List.length corners < 3 then raise (Bad (ln, "a face needs at least 3 corners"));
          let c = List.map (fun w ->
              match String.split_on_char '/' w with
              | [ v ] | [ v; _ ] -> (index "vertex" !nv v, -1)
              | [ v; _; n ] -> (index "vertex" !nv v, if n = "" then -1 else index "normal" !nn n)
              | _ -> raise (Bad (ln, Printf.sprintf "bad face corner %S" w))) corners in
          let g = match !current with Some g -> g | None -> group (base ^ "_default") in
          g.faces <- Array.of_list c :: g.faces
      | _ -> ()) lines;
  (Array.of_list (List.rev !verts), Array.of_list (List.rev !norms), List.rev !groups, base)

let fmt (x, y, z) = Printf.sprintf "<%.9g, %.9g, %.9g>" x y z

let mesh2 buf verts norms g =
  (* local vertex and normal numbering *)
  let vmap = Hashtbl.create 64 and vl = ref [] and nvl = ref 0 in
  let nmap = Hashtbl.create 64 and nl = ref [] and nnl = ref 0 in
  let local map l n key value =
    match Hashtbl.find_opt map key with
    | Some k -> k
    | None -> Hashtbl.add map key !n; l := value :: !l; incr n; !n - 1 in
  let tris = ref [] in
  List.iter (fun face ->
      let orig = Array.map fst face in
      let face = Array.map (fun (v, n) -> (local vmap vl nvl (`V v) verts.(v), n)) face in
      let smooth = Array.for_all (fun (_, n) -> n >= 0) face in
      for k = 1 to Array.length face - 2 do
        let a, na = face.(0) and b, nb = face.(k) and c, nc = face.(k + 1) in
        let oa = orig.(0) and ob = orig.(k) and oc = orig.(k + 1) in
        let ns =
          if smooth then (local nmap nl nnl (`N na) norms.(na), local nmap nl nnl (`N nb) norms.(nb),
                          local nmap nl nnl (`N nc) norms.(nc))
          else
            let (ax, ay, az) = verts.(oa) and (bx, by, bz) = verts.(ob) and (cx, cy, cz) = verts.(oc) in
            let ux, uy, uz = (bx -. ax, by -. ay, bz -. az) and wx, wy, wz = (cx -. ax, cy -. ay, cz -. az) in
            let n = ((uy *. wz) -. (uz *. wy), (uz *. wx) -. (ux *. wz), (ux *. wy) -. (uy *. wx)) in
            let (nx, ny, nz) = n in
            let n = if nx = 0. && ny = 0. && nz = 0. then (0., 1., 0.) else n in
            let k = local nmap nl nnl (`F (List.length !tris)) n in
            (k, k, k)
        in
        tris := ((a, b, c), ns) :: !tris
      done) (List.rev g.faces);
  let tris = List.rev !tris in
  let any_smooth = List.exists (fun f -> Array.for_all (fun (_, n) -> n >= 0) f) g.faces in
  let add = Buffer.add_string buf in
  add (Printf.sprintf "#declare %s = mesh2 {\n  vertex_vectors { %d" (ident g.name) !nvl);
  List.iter (fun v -> add (",\n    " ^ fmt v)) (List.rev !vl);
  if any_smooth then begin
    add (Printf.sprintf " }\n  normal_vectors { %d" !nnl);
    List.iter (fun v -> add (",\n    " ^ fmt v)) (List.rev !nl)
  end;
  add (Printf.sprintf " }\n  face_indices { %d" (List.length tris));
  List.iter (fun ((a, b, c), _) -> add (Printf.sprintf ",\n    <%d, %d, %d>" a b c)) tris;
  if any_smooth then begin
    add (Printf.sprintf " }\n  normal_indices { %d" (List.length tris));
    List.iter (fun (_, (a, b, c)) -> add (Printf.sprintf ",\n    <%d, %d, %d>" a b c)) tris
  end;
  add " }\n}\n\n"

let convert path =
  match In_channel.with_open_bin path In_channel.input_all with
  | exception Sys_error e -> Error e
  | text -> (
      match parse path text with
      | exception Bad (ln, msg) -> Error (Printf.sprintf "%s:%d: error: %s" path ln msg)
      | verts, norms, groups, base ->
          let groups = List.filter (fun g -> g.faces <> []) groups in
          if groups = [] then Error (Printf.sprintf "%s: error: no faces" path)
          else begin
            let buf = Buffer.create 4096 in
            Buffer.add_string buf (Printf.sprintf "// %s converted by camlray obj2pov\n\n" (Filename.basename path));
            (* distinct names for groups that share one *)
            let seen = Hashtbl.create 8 in
            let groups = List.map (fun g ->
                let n = Option.value ~default:0 (Hashtbl.find_opt seen g.name) in
                Hashtbl.replace seen g.name (n + 1);
                if n = 0 then g else { g with name = Printf.sprintf "%s_%d" g.name n }) groups in
            List.iter (mesh2 buf verts norms) groups;
            let objs = String.concat " " (List.map (fun g -> Printf.sprintf "object { %s }" (ident g.name)) groups) in
            Buffer.add_string buf
              (match groups with
               | [ g ] -> Printf.sprintf "#declare %s = object { %s }\n" (ident (base ^ "_all")) (ident g.name)
               | _ -> Printf.sprintf "#declare %s = union { %s }\n" (ident (base ^ "_all")) objs);
            Ok (Buffer.contents buf)
          end)

let run path =
  match convert path with
  | Ok s -> print_string s; 0
  | Error e -> prerr_endline ("camlray obj2pov: " ^ e); 1
