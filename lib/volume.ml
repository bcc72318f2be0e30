(* Media along a ray in whitted mode (see volume.mli). A sample at a
   point holds nine numbers: extinction, emitted plus scattered light, and
   scattered light alone (which decides method 3's subdivisions). *)

let slot = 9
let max_depth = 12

type st = {
  buf : Float.Array.t;  (** samples: 0 and 1 a stretch's ends, 2 + k a middle at depth k *)
  r : Ray.scratch;  (** the ray, its direction unit *)
  p : Vec3.m;
  pig : Pigment.out;
  dens : Color.acc;
  ext : Color.acc;
  lit : Color.acc;  (** the light scattered at a sample *)
  sum : Color.acc;  (** a stretch's mean of the second triple *)
  sumx : Color.acc;  (** its mean extinction *)
}

let key =
  Scratch.key (fun () ->
      { buf = Float.Array.make (slot * (max_depth + 3)) 0.; r = Ray.scratch (); p = Vec3.m ();
        pig = Pigment.out (); dens = Color.acc 0.; ext = Color.acc 0.; lit = Color.acc 0.;
        sum = Color.acc 0.; sumx = Color.acc 0. })

(* the light of every media-interacting light reaching [p], each weighted
   by the phase of [sc] toward the eye, into [st.lit] *)
let in_scatter (s : Scene.t) st (sc : Media.scattering) (p : Vec3.m) =
  let lit = st.lit and r = st.r in
  Color.acc_set lit 0. 0. 0.;
  let w = Shadow.walk () in
  let l = Shadow.toward w in
  for i = 0 to Array.length s.lights - 1 do
    let light = s.lights.(i) in
    if light.media_interaction then begin
      Light.direction_into light p l;
      let att = Light.attenuation_m light p in
      if att > 0. then begin
        let sr, sg, sb =
          if light.shadowless then (1., 1., 1.)
          else begin
            Shadow.light s w light p;
            let a = Shadow.passed w in
            (a.ar, a.ag, a.ab)
          end
        in
        (* the light travels along -l, the eye is back along the ray *)
        let c = (l.lx *. r.dx) +. (l.ly *. r.dy) +. (l.lz *. r.dz) in
        let k = att *. Media.phase sc c in
        Color.acc_set lit
          (lit.ar +. (k *. sr *. light.color.r))
          (lit.ag +. (k *. sg *. light.color.g))
          (lit.ab +. (k *. sb *. light.color.b))
      end
    end
  done

(* the sample at [x] along the ray into slot [k] *)
let sample s st (inside : Interior.t list) x k =
  let r = st.r and p = st.p in
  Vec3.set p (r.ox +. (x *. r.dx)) (r.oy +. (x *. r.dy)) (r.oz +. (x *. r.dz));
  let b = st.buf and o = k * slot in
  for j = 0 to slot - 1 do
    Float.Array.set b (o + j) 0.
  done;
  List.iter
    (fun (i : Interior.t) ->
      List.iter
        (fun (m : Media.t) ->
          Color.acc_set st.ext 0. 0. 0.;
          Media.add_extinction m p st.pig st.dens st.ext;
          (* [add_extinction] left the density in [dens] *)
          let dr, dg, db = if Media.constant m then (1., 1., 1.) else (st.dens.ar, st.dens.ag, st.dens.ab) in
          let add j v = Float.Array.set b (o + j) (Float.Array.get b (o + j) +. v) in
          add 0 st.ext.ar;
          add 1 st.ext.ag;
          add 2 st.ext.ab;
          add 3 (dr *. m.emission.r);
          add 4 (dg *. m.emission.g);
          add 5 (db *. m.emission.b);
          match m.scattering with
          | None -> ()
          | Some sc ->
              in_scatter s st sc p;
              let lr = dr *. sc.color.r *. st.lit.ar
              and lg = dg *. sc.color.g *. st.lit.ag
              and lb = db *. sc.color.b *. st.lit.ab in
              add 3 lr; add 4 lg; add 5 lb; add 6 lr; add 7 lg; add 8 lb)
        i.media)
    inside

let differ st ka kb thr =
  let b = st.buf in
  let d j = Float.abs (Float.Array.get b ((ka * slot) + j) -. Float.Array.get b ((kb * slot) + j)) in
  d 6 > thr || d 7 > thr || d 8 > thr

(* a stretch [a, b] whose ends are in slots [ka], [kb], its middle read
   into slot 2 + depth, split while its scattered light differs by more
   than [thr] ([level] splits left): [w] times its mean added to [sum]
   and [sumx] *)
let rec stretch s st inside a b ka kb depth level thr w =
  let km = 2 + depth in
  sample s st inside (0.5 *. (a +. b)) km;
  if level > 0 && depth < max_depth && (differ st ka km thr || differ st km kb thr) then begin
    let m = 0.5 *. (a +. b) in
    stretch s st inside a m ka km (depth + 1) (level - 1) thr (0.5 *. w);
    stretch s st inside m b km kb (depth + 1) (level - 1) thr (0.5 *. w)
  end
  else begin
    let bf = st.buf and k = w /. 3. in
    let g kk j = Float.Array.get bf ((kk * slot) + j) in
    let m j = k *. (g ka j +. g km j +. g kb j) in
    Color.acc_set st.sumx (st.sumx.ar +. m 0) (st.sumx.ag +. m 1) (st.sumx.ab +. m 2);
    Color.acc_set st.sum (st.sum.ar +. m 3) (st.sum.ag +. m 4) (st.sum.ab +. m 5)
  end

let rec first_medium = function
  | [] -> None
  | (i : Interior.t) :: r -> ( match i.media with m :: _ -> Some m | [] -> first_medium r)

let apply (s : Scene.t) (o : Vec3.m) (d : Vec3.m) t inside (out : Color.acc) =
  match first_medium inside with
  | None -> ()
  | Some m0 when Float.is_finite t ->
      let st = Scratch.get key in
      let dl = Float.sqrt ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz)) in
      let r = st.r in
      r.ox <- o.mx; r.oy <- o.my; r.oz <- o.mz;
      r.dx <- d.mx /. dl; r.dy <- d.my /. dl; r.dz <- d.mz /. dl;
      let len = t *. dl in
      let n = Media.pieces m0 in
      let w = len /. float_of_int n in
      (* optical depth so far, light gathered *)
      let odr = ref 0. and odg = ref 0. and odb = ref 0. in
      let gr = ref 0. and gg = ref 0. and gb = ref 0. in
      let gather mid =
        (* a stretch's light, dimmed by the depth before it ([mid]: half
           of its own too, method 2) *)
        let x = st.sumx and c = st.sum in
        let h = if mid then 0.5 else 0. in
        gr := !gr +. (c.ar *. Float.exp (-. (!odr +. (h *. x.ar))));
        gg := !gg +. (c.ag *. Float.exp (-. (!odg +. (h *. x.ag))));
        gb := !gb +. (c.ab *. Float.exp (-. (!odb +. (h *. x.ab))));
        odr := !odr +. x.ar;
        odg := !odg +. x.ag;
        odb := !odb +. x.ab
      in
      if m0.meth = 2 then
        for i = 0 to n - 1 do
          sample s st inside (len *. (float_of_int i +. 0.5) /. float_of_int n) 0;
          let g j = w *. Float.Array.get st.buf j in
          Color.acc_set st.sumx (g 0) (g 1) (g 2);
          Color.acc_set st.sum (g 3) (g 4) (g 5);
          gather true
        done
      else begin
        let step = len /. float_of_int (n + 1) in
        sample s st inside 0. 0;
        for i = 0 to n - 1 do
          let a = step *. float_of_int i in
          (* ends alternate between slots 0 and 1 *)
          let ka = i land 1 and kb = 1 - (i land 1) in
          sample s st inside (a +. step) kb;
          Color.acc_set st.sumx 0. 0. 0.;
          Color.acc_set st.sum 0. 0. 0.;
          stretch s st inside a (a +. step) ka kb 0 m0.aa_level m0.aa_threshold w;
          gather false
        done
      end;
      Color.acc_set out
        ((out.ar *. Float.exp (-. !odr)) +. !gr)
        ((out.ag *. Float.exp (-. !odg)) +. !gg)
        ((out.ab *. Float.exp (-. !odb)) +. !gb)
  | Some _ -> ()
