// Perturbed normals that tilt away from the eye, seen at a grazing angle:
// POV-Ray keeps such a normal as it is (the light in front misses it, and
// a reflected ray sent below the surface is mended about the surface's
// own normal; a refracted ray bends about the normal's opposite).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -6> look_at <0, 0, 4> angle 50 }
light_source { <-4, 8, -3> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0
  pigment { checker rgb <0.9, 0.8, 0.6> rgb <0.4, 0.5, 0.3> scale 0.7 }
  normal { onion 6 scale 0.3 }
  finish { diffuse 0.8 ambient 0.1 phong 0.6 reflection 0.25 }
}
sphere { <-1.3, 1, 2>, 1
  pigment { rgb <0.9, 0.3, 0.2> }
  normal { leopard 6 scale 0.15 }
  finish { reflection 0.4 phong 1 specular 0.5 }
}
sphere { <1.3, 1, 2>, 1
  pigment { rgbf <0.9, 1, 0.9, 0.9> }
  normal { onion 6 scale 0.2 }
  finish { reflection 0.1 phong 0.8 }
  interior { ior 1.5 }
}
