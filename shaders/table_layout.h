// The layout of the subsurface tables as GPU textures, in one place. This file is valid C++ and GLSL (comments and
// #defines only): the uploader (app/render/table_textures.cpp) includes it, and every shader program is prefixed
// with it (app/render/renderer.cpp).
//
// Two GL_TEXTURE_2D_ARRAY textures, RGBA32F, linear filtering, clamp to edge:
//   u_reflection    the subsurface BRDF's Fourier coefficients S_m   [1/sr]
//   u_transmission  the layer BTDF's Fourier coefficients B_m        [1/sr]
// layer m          Fourier mode m, graphics azimuth convention: f(theta_i, theta_o, phi) = sum_m value_m cos(m phi)
// texel (col, row) (theta_o, theta_i); both axes sample x = index / (size - 1) on the tables' grid map
//                  theta = (pi/2) sin(pi x / 2) (core/series/layer_tables.h), so a coordinate is x =
// asin(theta/(pi/2))/(pi/2)
//                  and the texture coordinate is (x (size - 1) + 0.5) / size
// size             SKINLAYER_TABLE_UPSAMPLE (K - 1) + 1 texels per axis, resampled from the K-point spline tables;
//                  K is the finest of the channels' grids (each channel is solved on the grid it needs)
// channels         R, G, B: the layer solved with the red, green and blue single-scattering albedo; A unused
#define SKINLAYER_TABLE_UPSAMPLE 2
