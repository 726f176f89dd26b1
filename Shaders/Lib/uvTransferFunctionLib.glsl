// The transfer function's nodes and the Psi table as the fragment stages of both mappers read them
// (inserted at "//UV::TransferFunction"). Nodes: normalised scalar, colour and extinction, linear in
// between, constant beyond the ends (uvOpticalModel.h); up to UV_MAX_UNIFORM_NODES as uniforms,
// cheaper to read than a texture on CPU rasterisers, or a texture when UV_NODE_TEXTURE is defined.
#ifdef UV_NODE_TEXTURE
uniform sampler2D transferFunction; // nodes: row 0 (r, g, b, extinction), row 1 (normalised scalar)
#else
uniform vec4 nodeValues[UV_MAX_UNIFORM_NODES];        // (r, g, b, extinction)
uniform vec4 nodeScalars[UV_MAX_UNIFORM_NODES / 4];   // normalised scalars, four per vec4
#endif
uniform int nodeCount;
uniform sampler2D psiTable;         // Psi over gamma = sqrt(x) / (1 + sqrt(x)), both axes
uniform float psiTableSize;

const float psiSeriesLimit = 1e-2; // as uv::PsiSeriesLimit

float NodeScalar(int k)
{
#ifdef UV_NODE_TEXTURE
  return texelFetch(transferFunction, ivec2(k, 1), 0).r;
#else
  return nodeScalars[k >> 2][k & 3];
#endif
}

/// Node k's (r, g, b, extinction).
vec4 NodeValue(int k)
{
#ifdef UV_NODE_TEXTURE
  return texelFetch(transferFunction, ivec2(k, 0), 0);
#else
  return nodeValues[k];
#endif
}

/// Number of nodes with scalar <= s (binary search).
int NodesAtOrBelow(float s)
{
  int low = 0, high = nodeCount; // the answer is in [low, high]
  while (low < high)
  {
    int middle = (low + high) / 2;
    if (NodeScalar(middle) <= s)
      low = middle + 1;
    else
      high = middle;
  }
  return low;
}

/// Number of nodes with scalar < s (binary search).
int NodesBelow(float s)
{
  int low = 0, high = nodeCount; // the answer is in [low, high]
  while (low < high)
  {
    int middle = (low + high) / 2;
    if (NodeScalar(middle) < s)
      low = middle + 1;
    else
      high = middle;
  }
  return low;
}

/// (r, g, b, extinction) at s, given `below` = the number of nodes <= s.
vec4 EvaluateBetween(float s, int below)
{
  if (below <= 0)
    return NodeValue(0);
  if (below >= nodeCount)
    return NodeValue(nodeCount - 1);
  float s0 = NodeScalar(below - 1), s1 = NodeScalar(below);
  return mix(NodeValue(below - 1), NodeValue(below), s1 > s0 ? clamp((s - s0) / (s1 - s0), 0.0, 1.0) : 0.0);
}

/// Mean transmittance of a linear piece of optical depths a (front) and b (back): the table, or its
/// series for small depths (uvPreIntegration.h).
float Psi(float a, float b)
{
  if (a + b < psiSeriesLimit)
  {
    float k = b - a;
    return 1.0 - (a / 2.0 + k / 6.0) + 0.5 * (a * a / 3.0 + a * k / 4.0 + k * k / 20.0);
  }
  vec2 root = sqrt(vec2(a, b));
  vec2 gamma = root / (1.0 + root);
#ifdef UV_TEXTURE_UNIT_FILTER
  return textureLod(psiTable, (gamma * (psiTableSize - 1.0) + 0.5) / psiTableSize, 0.0).r;
#else
  // Bilinear with float weights from four fetches: a texture unit's own filter may round its
  // weights (GL leaves their precision to the implementation; uvgl::ExactTextureFilter).
  vec2 x = gamma * (psiTableSize - 1.0);
  vec2 below = floor(x), f = x - below;
  int last = int(psiTableSize) - 1;
  ivec2 i0 = min(ivec2(below), ivec2(last)), i1 = min(i0 + 1, ivec2(last));
  float near = mix(texelFetch(psiTable, i0, 0).r, texelFetch(psiTable, ivec2(i1.x, i0.y), 0).r, f.x);
  float far = mix(texelFetch(psiTable, ivec2(i0.x, i1.y), 0).r, texelFetch(psiTable, i1, 0).r, f.x);
  return mix(near, far, f.y);
#endif
}
