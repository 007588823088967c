// The test scene: a floor and five spheres of roughness 0.1 to 0.9 under a rectangular area light, seen from
// above at a normal angle (left half of the canvas) and at a grazing angle (right half), and a sixth sphere
// whose sheen is lit through pbrfit's Charlie LTC tables by a custom shader chunk. The LTC tables come from
// three.js (tables=three), from pbrfit's export of the published table it holds beside its fit
// (tables=published: the same numbers as three.js's), from pbrfit's export of its own GGX fit (tables=pbrfit),
// or from that fit exported with its axes swapped (tables=transposed: `--u-axis sqrt_one_minus_cos`, which must
// look wrong). When done, window.renderResult holds
// the canvas's RGBA pixels (row 0 at the top) or the error that stopped it. The exported modules are in
// ./exported/ (rect_area_light_test.mjs serves them): <stem>_1.js, <stem>_2.js and their _half versions for
// stem ltc (pbrfit's fit), published and transposed, charlie_1.js and charlie_2.js.
import * as THREE from 'three';
import { RectAreaLightUniformsLib } from 'three/addons/lights/RectAreaLightUniformsLib.js';

const SIZE = 256;  // per view

function table(data, type) {
  const t = new THREE.DataTexture(data, 64, 64, THREE.RGBAFormat, type, THREE.UVMapping, THREE.ClampToEdgeWrapping,
                                  THREE.ClampToEdgeWrapping, THREE.LinearFilter, THREE.NearestFilter, 1);
  t.needsUpdate = true;
  return t;
}

async function install(mode) {
  RectAreaLightUniformsLib.init();
  if (mode === 'three') return;
  const stem = mode === 'pbrfit' ? 'ltc' : mode;
  const [f1, f2, h1, h2] = await Promise.all([`${stem}_1.js`, `${stem}_2.js`, `${stem}_1_half.js`, `${stem}_2_half.js`]
      .map((name) => import('./exported/' + name)));
  THREE.UniformsLib.LTC_FLOAT_1 = table(f1.LTC_1_DATA, THREE.FloatType);
  THREE.UniformsLib.LTC_FLOAT_2 = table(f2.LTC_2_DATA, THREE.FloatType);
  THREE.UniformsLib.LTC_HALF_1 = table(h1.LTC_1_DATA, THREE.HalfFloatType);
  THREE.UniformsLib.LTC_HALF_2 = table(h2.LTC_2_DATA, THREE.HalfFloatType);
}

// A material whose rect-area specular reads pbrfit's Charlie sheen tables instead of the GGX ones: the same
// LTC evaluation (three.js's LTC_Evaluate) with the sheen lobe's inverse matrix and its norm as the colour.
async function sheenMaterial() {
  const s1 = await import('./exported/charlie_1.js'), s2 = await import('./exported/charlie_2.js');
  const width = s1.CHARLIE_1_WIDTH;
  const material = new THREE.MeshPhysicalMaterial({ color: 0x000000, roughness: 0.6, metalness: 0.0 });
  material.onBeforeCompile = (shader) => {
    shader.uniforms.sheenLtc1 = { value: new THREE.DataTexture(s1.CHARLIE_1_DATA, width, s1.CHARLIE_1_HEIGHT, THREE.RGBAFormat,
                                  THREE.FloatType, THREE.UVMapping, THREE.ClampToEdgeWrapping, THREE.ClampToEdgeWrapping, THREE.LinearFilter, THREE.NearestFilter) };
    shader.uniforms.sheenLtc2 = { value: new THREE.DataTexture(s2.CHARLIE_2_DATA, width, s2.CHARLIE_2_HEIGHT, THREE.RGBAFormat,
                                  THREE.FloatType, THREE.UVMapping, THREE.ClampToEdgeWrapping, THREE.ClampToEdgeWrapping, THREE.LinearFilter, THREE.NearestFilter) };
    shader.uniforms.sheenLtc1.value.needsUpdate = true;
    shader.uniforms.sheenLtc2.value.needsUpdate = true;
    const chunk = THREE.ShaderChunk.lights_physical_pars_fragment.replace(
        'vec2 uv = LTC_Uv( normal, viewDir, roughness );',
        `vec2 uv = vec2( roughness, sqrt( 1.0 - saturate( dot( normal, viewDir ) ) ) ) * ${(width - 1) / width} + ${0.5 / width};`)
      .replace('vec4 t1 = texture2D( ltc_1, uv );', 'vec4 t1 = texture2D( sheenLtc1, uv );')
      .replace('vec4 t2 = texture2D( ltc_2, uv );', 'vec4 t2 = texture2D( sheenLtc2, uv );')
      .replace('vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );',
               'vec3 fresnel = vec3( 2.7, 1.5, 2.4 ) * t2.x;');
    shader.fragmentShader = 'uniform sampler2D sheenLtc1;\nuniform sampler2D sheenLtc2;\n' +
        shader.fragmentShader.replace('#include <lights_physical_pars_fragment>', chunk);
    material.userData.patched = chunk.includes('texture2D( sheenLtc1, uv )') && chunk.includes('* t2.x;') &&
        shader.fragmentShader.includes('texture2D( sheenLtc2, uv )');
  };
  return material;
}

async function main() {
  const mode = new URLSearchParams(location.search).get('tables') || 'three';
  await install(mode);
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(2 * SIZE, SIZE);
  renderer.setScissorTest(true);
  document.body.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const light = new THREE.RectAreaLight(0xffffff, 2.5, 4, 1.2);
  light.position.set(0, 2.0, -1.8);
  light.lookAt(0, 0, 0.6);
  scene.add(light);
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(12, 12),
                               new THREE.MeshStandardMaterial({ color: 0x606060, roughness: 0.35, metalness: 0.8 }));
  floor.rotation.x = -Math.PI / 2;
  scene.add(floor);
  for (let i = 0; i < 5; ++i) {
    const sphere = new THREE.Mesh(new THREE.SphereGeometry(0.32, 64, 32),
                                  new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.1 + 0.2 * i, metalness: 1.0 }));
    sphere.position.set(-1.6 + 0.8 * i, 0.32, 0.5);
    scene.add(sphere);
  }
  const sheen = new THREE.Mesh(new THREE.SphereGeometry(0.32, 64, 32), await sheenMaterial());
  sheen.position.set(0, 0.32, 1.3);
  scene.add(sheen);

  const views = [[new THREE.Vector3(0, 4.5, 5.0), 0], [new THREE.Vector3(0, 0.7, 7.0), SIZE]];
  for (const [position, left] of views) {
    const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 50);
    camera.position.copy(position);
    camera.lookAt(0, 0.3, 0.6);
    renderer.setViewport(left, 0, SIZE, SIZE);
    renderer.setScissor(left, 0, SIZE, SIZE);
    renderer.render(scene, camera);
  }
  const gl = renderer.getContext();
  const pixels = new Uint8Array(2 * SIZE * SIZE * 4);
  gl.readPixels(0, 0, 2 * SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const rows = [];
  for (let y = SIZE - 1; y >= 0; --y) rows.push(...pixels.subarray(y * 2 * SIZE * 4, (y + 1) * 2 * SIZE * 4));
  window.renderResult = { width: 2 * SIZE, height: SIZE, pixels: rows, sheenPatched: sheen.material.userData.patched === true,
                          floatTables: renderer.extensions.has('OES_texture_float_linear') };
}

main().catch((error) => { window.renderResult = { error: String(error && error.stack || error) }; });
