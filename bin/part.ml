open Camlray

type meta = { region : Render.tile; width : int; height : int; id : string }

let ints s =
  let parts = String.split_on_char ',' s in
  let vs = List.map (fun p -> int_of_string_opt (String.trim p)) parts in
  if List.for_all Option.is_some vs then Some (List.map Option.get vs) else None

let parse_region s =
  match ints s with
  | Some [ x0; y0; x1; y1 ] -> Ok { Render.x0; y0; x1; y1 }
  | _ -> Error (Printf.sprintf "--region needs X0,Y0,X1,Y1 (four whole numbers), found %S" s)

let check_region ~width ~height (r : Render.tile) =
  if r.x0 < 0 || r.y0 < 0 || r.x1 > width || r.y1 > height || r.x0 >= r.x1 || r.y0 >= r.y1 then
    Error
      (Printf.sprintf "region %d,%d,%d,%d is empty or outside the %dx%d image" r.x0 r.y0 r.x1 r.y1
         width height)
  else Ok ()

let of_pov ~width ~height s =
  match String.split_on_char ',' s with
  | [ sr; er; sc; ec ] -> (
      let f v = if String.trim v = "" then None else float_of_string_opt (String.trim v) in
      let start n = function
        | None -> Some 0
        | Some v when v < 1. -> Some (int_of_float (Float.round (v *. float n)))
        | Some v -> Some (int_of_float v - 1)
      and stop n = function
        | None -> Some n
        | Some v when v < 1. -> Some (int_of_float (Float.round (v *. float n)))
        | Some v -> Some (int_of_float v)
      in
      match (start height (f sr), stop height (f er), start width (f sc), stop width (f ec)) with
      | Some y0, Some y1, Some x0, Some x1 -> Ok { Render.x0; y0; x1; y1 }
      | _ -> Error "bad +SR/+ER/+SC/+EC values")
  | _ -> Error "bad +SR/+ER/+SC/+EC values"

let text m =
  let r = m.region in
  [
    ("camlray:region", Printf.sprintf "%d,%d,%d,%d" r.x0 r.y0 r.x1 r.y1);
    ("camlray:size", Printf.sprintf "%d,%d" m.width m.height);
    ("camlray:render", m.id);
  ]

let of_text kv =
  match
    (List.assoc_opt "camlray:region" kv, List.assoc_opt "camlray:size" kv, List.assoc_opt "camlray:render" kv)
  with
  | Some r, Some s, Some id -> (
      match (parse_region r, ints s) with
      | Ok region, Some [ width; height ] -> Some { region; width; height; id }
      | _ -> None)
  | _ -> None

let merge parts out =
  let ( let* ) = Result.bind in
  let* metas =
    List.fold_left
      (fun acc p ->
        let* acc = acc in
        let* kv = try Ok (Image.png_text p) with Failure e | Sys_error e -> Error e in
        match of_text kv with
        | None -> Error (Printf.sprintf "%s is not a partial render of camlray (no region recorded)" p)
        | Some m -> (
            match Image.read p with
            | img ->
                if img.w <> m.region.x1 - m.region.x0 || img.h <> m.region.y1 - m.region.y0 then
                  Error (Printf.sprintf "%s: image size does not match its recorded region" p)
                else Ok ((p, m, img) :: acc)
            | exception (Failure e | Sys_error e) -> Error e))
      (Ok []) parts
  in
  match List.rev metas with
  | [] -> Error "merge needs at least one part"
  | (p0, m0, _) :: _ as all ->
      let* () =
        List.fold_left
          (fun acc (p, m, _) ->
            let* () = acc in
            if m.width <> m0.width || m.height <> m0.height then
              Error (Printf.sprintf "%s is from a %dx%d render, %s from a %dx%d one" p m.width m.height p0 m0.width m0.height)
            else if m.id <> m0.id then
              Error (Printf.sprintf "%s and %s are parts of different renders (scene or options differ)" p0 p)
            else Ok ())
          (Ok ()) all
      in
      let w = m0.width and h = m0.height in
      let owner = Array.make (w * h) (-1) in
      let data = Bytes.make (w * h * 3) '\000' in
      let* () =
        List.fold_left
          (fun acc (i, (p, m, (img : Image.rgb8))) ->
            let* () = acc in
            let r = m.region in
            let clash = ref None in
            for y = r.y0 to r.y1 - 1 do
              for x = r.x0 to r.x1 - 1 do
                let k = (y * w) + x in
                if owner.(k) >= 0 && !clash = None then clash := Some (x, y, owner.(k));
                owner.(k) <- i;
                Bytes.blit img.data ((((y - r.y0) * img.w) + (x - r.x0)) * 3) data (k * 3) 3
              done
            done;
            match !clash with
            | Some (x, y, j) ->
                let q, _, _ = List.nth all j in
                Error (Printf.sprintf "%s and %s overlap (pixel %d,%d)" q p x y)
            | None -> Ok ())
          (Ok ()) (List.mapi (fun i x -> (i, x)) all)
      in
      let missing = ref None in
      Array.iteri (fun k o -> if o < 0 && !missing = None then missing := Some k) owner;
      match !missing with
      | Some k ->
          let n = Array.fold_left (fun n o -> if o < 0 then n + 1 else n) 0 owner in
          Error (Printf.sprintf "the parts leave a gap: %d pixels missing, the first at %d,%d" n (k mod w) (k / w))
      | None -> (
          try
            Image.write_png out { Image.w; h; data };
            Ok ()
          with Failure e | Sys_error e -> Error (Printf.sprintf "cannot write %s: %s" out e))
