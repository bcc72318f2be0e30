// projected_through: a light reaches a point only when the ray from the
// point toward the light meets the object before the light (the object
// itself is never drawn and casts no shadow); only what lies between
// the point and that crossing casts shadows. A slide projector: a light
// behind a ring (a torus) and a star of boxes throws their shapes on
// the back wall; a bar between the slide and the light casts no shadow
// (the light has passed it), a ball between the slide and the wall
// does. The floor runs through a second light's projected_through
// sphere: lit where the sphere is seen from it, inside the sphere too
// (the ray's way out is a crossing before the light). A shadowless
// light keeps its projected_through (a third, through a box moved by a
// translate written after it); an area light tests every sample.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 2, 2> right x*image_width/image_height angle 60 }
background { rgb <0.02, 0.02, 0.04> }

plane { -z, -5 pigment { rgb 0.85 } finish { ambient 0.08 diffuse 0.8 } }
plane { y, 0 pigment { rgb <0.7, 0.72, 0.75> } finish { ambient 0.08 diffuse 0.8 } }
light_source { <0, 8, -8>, rgb 0.15 }

#declare Slide = union {
  torus { 0.8, 0.1 rotate 90*x }
  box { <-0.5, -0.08, -0.02>, <0.5, 0.08, 0.02> }
  box { <-0.5, -0.08, -0.02>, <0.5, 0.08, 0.02> rotate 60*z }
  box { <-0.5, -0.08, -0.02>, <0.5, 0.08, 0.02> rotate -60*z }
}
object { Slide translate <-1, 2.5, -3> pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0.2 } }
// between the slide and its light: no shadow
cylinder { <-2.2, 2.5, -5.2>, <0.2, 2.5, -5.2>, 0.05 pigment { rgb <0.4, 0.4, 0.8> } }
// between the slide and the wall: a shadow in the projected light
sphere { <-0.7, 2.3, 1>, 0.3 pigment { rgb <0.8, 0.3, 0.3> } }

light_source { <-1, 2.5, -7>, rgb <1, 0.95, 0.8> * 1.5 projected_through { Slide translate <-1, 2.5, -3> } }

// the floor runs through this one's sphere
light_source { <2.5, 4, 0>, rgb <0.5, 0.8, 1> projected_through { sphere { <2.5, 0, 1>, 0.9 } } }

// shadowless, through a box placed by the translate after it
light_source { <0, 0, 0>, rgb <0.6, 1, 0.5> shadowless
  projected_through { box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> translate <0, 0, 2> } }
  translate <3, 3, -3> }

// an area light: each sample through the window or not
light_source { <-3.5, 5, -2>, rgb <1, 0.6, 0.8> area_light <0.6, 0, 0>, <0, 0.6, 0>, 3, 3 adaptive 1
  projected_through { box { <-3.9, 2.4, -0.1>, <-3.1, 3.2, 0.1> } } }
