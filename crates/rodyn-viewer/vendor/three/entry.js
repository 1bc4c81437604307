// What the vendored three.min.js exports (bundled by refresh.sh; see README.md).
export * from 'three';
export { OrbitControls } from 'three/addons/controls/OrbitControls.js';
export { STLLoader } from 'three/addons/loaders/STLLoader.js';
export { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
export { ColladaLoader } from 'three/addons/loaders/ColladaLoader.js';
