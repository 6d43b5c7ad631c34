// Progressive Monte Carlo estimate of the sphere's radiance under the environment, added to a float target:
//   L(n) = int f(l, v) L_env(l) max(0, n.l) dl
// with three sampling strategies per sample, combined by the balance heuristic (Veach 1997, multi-sample model):
// the environment's luminance (shaders/environment.glsl), the cosine about n (the subsurface term's shape) and the
// Beckmann distribution of facet normals about n reflected about the view (the surface term's lobe). Each sample adds
//   sum_s f(l_s) L_env(l_s) (n.l_s) / (p_env(l_s) + p_cos(l_s) + p_beckmann(l_s))
// to RGB and 1 to alpha (additive blending); the display divides. The sample points are randomized quasi-Monte
// Carlo: sample i of a pixel takes the i-th point of the (0, 2)-sequence (the base-2 radical inverse and Sobol's
// second dimension) shifted by a random offset per pixel and strategy (Cranley & Patterson 1976), so that the
// strategies' points stay evenly spread over their square as samples accumulate; the error then falls faster than
// N^{-1/2} (measured in docs/benchmarks.md).
in vec2 v_ndc;
out vec4 o_sum;

uniform vec2 u_extent;
uniform int u_samples;       // samples this pass
uniform int u_first_sample;  // samples added before this pass
uniform uint u_seed;         // the accumulation's random stream

uint g_state;
// PCG (O'Neill 2014) as a per-pixel stream.
float next_uniform() {
  g_state = g_state * 747796405u + 2891336453u;
  uint word = ((g_state >> ((g_state >> 28u) + 4u)) ^ g_state) * 277803737u;
  word = (word >> 22u) ^ word;
  return float(word >> 8u) * (1.0 / 16777216.0);
}

// The i-th point of the (0, 2)-sequence: the bit-reversed index, and Sobol's second dimension.
vec2 sequence_point(uint i) {
  uint reversed = i;
  reversed = (reversed << 16u) | (reversed >> 16u);
  reversed = ((reversed & 0x00ff00ffu) << 8u) | ((reversed & 0xff00ff00u) >> 8u);
  reversed = ((reversed & 0x0f0f0f0fu) << 4u) | ((reversed & 0xf0f0f0f0u) >> 4u);
  reversed = ((reversed & 0x33333333u) << 2u) | ((reversed & 0xccccccccu) >> 2u);
  reversed = ((reversed & 0x55555555u) << 1u) | ((reversed & 0xaaaaaaaau) >> 1u);
  uint sobol = 0u;
  for (uint v = 1u << 31u, k = i; k != 0u; k >>= 1u, v ^= v >> 1u) {
    if ((k & 1u) != 0u) sobol ^= v;
  }
  return vec2(float(reversed >> 8u), float(sobol >> 8u)) * (1.0 / 16777216.0);
}

// An orthonormal frame about n.
mat3 frame_about(vec3 n) {
  vec3 t = abs(n.z) < 0.999 ? normalize(cross(vec3(0.0, 0.0, 1.0), n)) : vec3(1.0, 0.0, 0.0);
  return mat3(t, cross(n, t), n);
}

// Density of the Beckmann strategy: h ~ D(h) (n.h), l = reflect(-v, h); p(l) = D(h) (n.h) / (4 |v.h|), h the one of
// +-normalize(l + v) on n's side (reflection about h and about -h give the same l).
float beckmann_pdf(vec3 n, vec3 l, vec3 v) {
  vec3 sum = l + v;
  if (dot(sum, sum) < 1e-12) return 0.0;
  vec3 h = normalize(sum);
  if (dot(n, h) < 0.0) h = -h;
  float vh = abs(dot(v, h));
  if (vh <= 0.0) return 0.0;
  float nh = dot(n, h);
  return beckmann_ndf(nh, u_sigma) * nh / (4.0 * vh);
}

vec3 contribution(vec3 n, vec3 l, vec3 v) {
  float cos_l = dot(n, l);
  if (cos_l <= 0.0) return vec3(0.0);
  float pdf = environment_pdf(l) + cos_l / kPi + beckmann_pdf(n, l, v);
  if (pdf <= 0.0) return vec3(0.0);
  return sphere_brdf(n, l, v) * environment_radiance(l) * cos_l / pdf;
}

void main() {
  // Texels whose centre lies more than 1.5 texel diagonals outside the limb are never read (the display's bilinear
  // filter reaches a texel only from within one diagonal of its centre; length(fwidth(p)) is the diagonal here).
  // Skipping them saves about a tenth of each pass (bench_render: BM_EnvironmentFramePieces).
  vec2 p = v_ndc * u_extent;
  if (length(p) > 1.0 + 1.5 * length(fwidth(p))) discard;
  vec3 n = sphere_normal(p);
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (n.z <= 0.0) n = normalize(n + vec3(0.0, 0.0, 1e-3));  // the silhouette: just inside it
  g_state = uint(gl_FragCoord.x) * 1973u + uint(gl_FragCoord.y) * 9277u + u_seed * 26699u;
  next_uniform();
  // One random shift per strategy for this pixel and stream.
  vec2 shift_env = vec2(next_uniform(), next_uniform());
  vec2 shift_cos = vec2(next_uniform(), next_uniform());
  vec2 shift_facet = vec2(next_uniform(), next_uniform());
  mat3 local = frame_about(n);
  vec3 sum = vec3(0.0);
  for (int s = 0; s < u_samples; ++s) {
    vec2 point = sequence_point(uint(u_first_sample + s));
    // The environment.
    sum += contribution(n, sample_environment(fract(point + shift_env)), v);
    // The cosine about n (Malley's method).
    vec2 xi = fract(point + shift_cos);
    float r = sqrt(xi.x), a = 2.0 * kPi * xi.y;
    sum += contribution(n, local * vec3(r * cos(a), r * sin(a), sqrt(max(0.0, 1.0 - r * r))), v);
    // A Beckmann facet normal: tan^2(alpha) = -sigma^2 ln(1 - xi).
    xi = fract(point + shift_facet);
    float t2 = -u_sigma * u_sigma * log(max(1e-12, 1.0 - xi.x));
    float cos_h = 1.0 / sqrt(1.0 + t2), sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h)), b = 2.0 * kPi * xi.y;
    vec3 h = local * vec3(sin_h * cos(b), sin_h * sin(b), cos_h);
    sum += contribution(n, reflect(-v, h), v);
  }
  o_sum = vec4(sum, float(u_samples));
}
