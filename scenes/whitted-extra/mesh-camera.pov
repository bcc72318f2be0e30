// POV-Ray's mesh_camera: a mesh with one face per pixel, row by row (face
// y * image_width + x for pixel (x, y); POV-Ray 3.7.0 reads image row j
// from face row j - 1, so the picture sits one row low, its top row
// doubled), each a small triangle across the line from the origin
// through the pixel's point of the plane z = 1, so that its centroid is
// that point and its normal that line (a pinhole camera, as
// meshcam_macros.inc builds one). Two rays a pixel (distribution 0: ray k
// from mesh k), from the mesh placed by a transform and from the same
// mesh turned a little more; location's z moves each ray's start 0.2
// along it.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare W = image_width;
#declare H = image_height;
#declare Aspect = W / H;
#declare S = 0.2 / W;  // the triangles' size: well inside a pixel
#declare Pinhole = mesh {
  #declare J = 0;
  #while (J < H)
    #declare I = 0;
    #while (I < W)
      #declare C = <((I + 0.5) / W - 0.5) * Aspect, 0.5 - (J + 0.5) / H, 1>;
      #declare D = vnormalize(C);
      #declare U = vnormalize(vcross(y, D));
      #declare V = vcross(D, U);
      triangle { C + S * V, C + S * (0.866 * U - 0.5 * V), C + S * (-0.866 * U - 0.5 * V) }
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
}
#declare Place = transform { rotate <20, -15, 0> translate <1.5, 2.2, -5> }
camera {
  mesh_camera {
    2 0
    mesh { Pinhole transform { Place } }
    mesh { Pinhole rotate 0.15*y transform { Place } }
  }
  location <0, 0, 0.2>
}
light_source { <4, 10, -6> rgb 1 }
light_source { <-6, 6, -2> rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.35 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-1.8, 0.6, 1.2>, 0.6 pigment { rgb <0.2, 0.5, 0.9> } finish { reflection 0.3 } }
sphere { <1.5, 0.5, 1.5>, 0.5 pigment { rgb <0.3, 0.8, 0.3> } }
box { <-0.4, 0, -2.4>, <0.4, 0.8, -1.6> rotate 30*y pigment { rgb <0.9, 0.8, 0.3> } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.3, 0.4, 0.8>] } } }
