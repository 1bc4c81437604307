// rodyn viewer: draws the scene JSON above with three.js (the global THREE,
// defined once its gzip-compressed block is inflated, as are the meshes).
// The producer computed every pose of a trajectory; this script composes
// joint transforms along the parent array only for the joint sliders, and
// interpolates a trajectory's poses between its samples.
// The URL fragment may say t=1.5 (time, paused), q=a,b,… (sliders),
// show=frames,com,… or show=all, and hide=robot,… (layers), joined by &.
// The body's data-status says "ready" once a frame is drawn, or "error: …".
'use strict';

const $ = (id) => document.getElementById(id);
// A page inside a frame (a test harness) also tells its parent.
const report = (status) => {
  document.body.dataset.status = status;
  if (window.parent !== window) window.parent.postMessage(status, '*');
};
const fail = (message) => {
  report('error: ' + message);
  $('status').textContent = message;
};
window.addEventListener('error', (e) => fail(e.message));
const consoleError = console.error;
console.error = (...args) => { fail(args.join(' ')); consoleError(...args); };
const S = JSON.parse($('scene').textContent);

// A gzip-compressed base64 block's bytes (the browser's own inflater: the
// page stays one file that opens offline).
const bytes = (b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
const inflate = async (b64) => new Uint8Array(await new Response(
  new Blob([bytes(b64)]).stream().pipeThrough(new DecompressionStream('gzip'))).arrayBuffer());

(async () => {
  const three = document.createElement('script');
  three.textContent = new TextDecoder().decode(await inflate($('three').textContent.trim()));
  document.head.append(three); // runs it: THREE is defined from here on
  start(await Promise.all(S.meshes.map((m) => inflate(m.gzip))));
})().catch((e) => fail(e && e.message ? e.message : String(e)));

// The page, once three.js and the mesh files (their bytes) are at hand.
function start(meshBytes) {

  const V3 = (a) => new THREE.Vector3(a[0], a[1], a[2]);
  // A pose as the producer writes it: rotation rows, then translation.
  const matrixOf = (p, o = 0) => new THREE.Matrix4().set(
    p[o], p[o + 1], p[o + 2], p[o + 9], p[o + 3], p[o + 4], p[o + 5], p[o + 10],
    p[o + 6], p[o + 7], p[o + 8], p[o + 11], 0, 0, 0, 1);
  const fragment = new URLSearchParams(location.hash.slice(1));

  // Renderer, camera, light, ground.
  const view = $('view');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  const up = V3(S.up).normalize();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.copy(up);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2).translateOnAxis(up, 10));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(3, -2, 5);
  scene.add(sun);

  // One group per body; its matrix is the body's world pose.
  const frames = S.bodies.map(() => {
    const g = new THREE.Group();
    g.matrixAutoUpdate = false;
    scene.add(g);
    return g;
  });
  const holder = (body) => (body === null ? scene : frames[body]);
  const layers = { robot: [], axes: [], frames: [], com: [], inertia: [], endpoints: [], contacts: [] };
  const put = (layer, parent, object) => { parent.add(object); layers[layer].push(object); return object; };
  // The model's size: its longest chain of joint offsets, plus an endpoint.
  const reach = [];
  S.bodies.forEach((b, i) => { reach[i] = (b.parent === null ? 0 : reach[b.parent]) + V3(b.placement.slice(9)).length(); });
  const size = Math.max(0.2, Math.max(0, ...reach) + S.endpoints.reduce((s, e) => Math.max(s, V3(e.position).length()), 0));
  const material = (c, fallback = 0x9aa3b0) => new THREE.MeshStandardMaterial({
    color: c ? new THREE.Color(c[0], c[1], c[2]) : fallback, opacity: c ? c[3] : 1,
    transparent: !!c && c[3] < 1, roughness: 0.6, metalness: 0.1,
  });

  // Visual geometry: URDF shapes and meshes.
  const meshes = S.meshes.map((m, k) => {
    const data = meshBytes[k];
    if (m.format === 'stl') return new THREE.STLLoader().parse(data.buffer);
    const text = new TextDecoder().decode(data);
    if (m.format === 'obj') return new THREE.OBJLoader().parse(text);
    const dae = new THREE.ColladaLoader().parse(text, '').scene;
    dae.rotation.set(0, 0, 0); // the loader turns Z_UP files to y up; the URDF frame is the file's
    return dae;
  });
  for (const v of S.visuals) {
    const g = v.geometry;
    let object;
    if (g.type === 'mesh') {
      const source = meshes[g.mesh];
      object = source.isBufferGeometry ? new THREE.Mesh(source, material(v.color)) : source.clone();
      if (v.color && !source.isBufferGeometry && S.meshes[g.mesh].format === 'obj') {
        object.traverse((o) => { if (o.isMesh) o.material = material(v.color); });
      }
      object.scale.set(g.scale[0], g.scale[1], g.scale[2]);
    } else {
      const shape = g.type === 'box' ? new THREE.BoxGeometry(g.size[0], g.size[1], g.size[2])
        : g.type === 'sphere' ? new THREE.SphereGeometry(g.radius, 32, 16)
          : new THREE.CylinderGeometry(g.radius, g.radius, g.length, 32).rotateX(Math.PI / 2);
      object = new THREE.Mesh(shape, material(v.color));
    }
    const at = new THREE.Group();
    at.matrixAutoUpdate = false;
    at.matrix.copy(matrixOf(v.pose));
    at.add(object);
    put('robot', holder(v.body), at);
  }

  // Without visual geometry: capsules from each joint to its children's
  // joints and its endpoints (to its centre of mass when it has neither).
  const radius = THREE.MathUtils.clamp(0.015 * size, 0.004, 0.05);
  const capsule = (parent, to, colour) => {
    const d = V3(to);
    if (d.length() < 1e-6) return;
    const c = new THREE.Mesh(new THREE.CapsuleGeometry(radius, d.length(), 6, 16), material(null, colour));
    c.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), d.clone().normalize());
    c.position.copy(d).multiplyScalar(0.5);
    put('robot', parent, c);
  };
  if (S.visuals.length === 0) {
    S.bodies.forEach((b, i) => {
      const ends = S.bodies.filter((c) => c.parent === i).map((c) => c.placement.slice(9))
        .concat(S.endpoints.filter((e) => e.body === i).map((e) => e.position));
      if (ends.length === 0 && b.mass > 0) ends.push(b.com);
      ends.forEach((p) => capsule(frames[i], p, 0x8a94a6));
      put('robot', frames[i], new THREE.Mesh(new THREE.SphereGeometry(radius * 1.6, 24, 12), material(null, 0x4a5568)));
    });
  }

  // Joint axes, body frames, centres of mass, inertia ellipsoids, endpoints.
  const dot = (r, colour) => new THREE.Mesh(new THREE.SphereGeometry(r, 16, 8), material(null, colour));
  S.bodies.forEach((b, i) => {
    const f = frames[i];
    if (b.joint.axis) {
      put('axes', f, new THREE.ArrowHelper(V3(b.joint.axis), new THREE.Vector3(), 0.15 * size, 0xff6f00, 0.03 * size, 0.018 * size));
    }
    put('frames', f, new THREE.AxesHelper(0.12 * size));
    if (b.mass > 0) put('com', f, dot(radius * 1.2, 0x111111)).position.copy(V3(b.com));
    if (b.ellipsoid) {
      const e = b.ellipsoid;
      const m = new THREE.Mesh(new THREE.SphereGeometry(1, 24, 12), material([0.2, 0.5, 0.9, 0.25]));
      m.matrixAutoUpdate = false;
      m.matrix.copy(matrixOf(e.axes.concat(b.com))).multiply(new THREE.Matrix4().makeScale(...e.radii.map((r) => Math.max(r, 1e-4))));
      put('inertia', f, m);
    }
  });
  S.endpoints.forEach((e) => put('endpoints', holder(e.body), dot(radius * 0.9, 0x7b1fa2)).position.copy(V3(e.position)));

  // Contacts of a trajectory: a dot at the point, an arrow for the force
  // (the robot's weight 1.5 times the radius of its bounding sphere), drawn
  // over the robot so that the legs do not hide them.
  let scale = size;
  const T = S.trajectory;
  const end = T ? T.t[T.t.length - 1] : 0;
  let time = 0;
  const visible = {};
  const weight = 9.81 * Math.max(S.bodies.reduce((s, b) => s + b.mass, 0), 1e-6);
  const contactCount = T ? Math.max(0, ...T.contacts.map((c) => c.length / 6)) : 0;
  const onTop = (object) => {
    object.renderOrder = 1;
    object.traverse((o) => { if (o.material) o.material.depthTest = false; });
    return object;
  };
  const contactMarks = Array.from({ length: contactCount }, () => ({
    point: put('contacts', scene, onTop(dot(radius * 1.1, 0xd32f2f))),
    arrow: put('contacts', scene, onTop(new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, 0xd32f2f))),
  }));
  const showContacts = (flat) => contactMarks.forEach((mark, k) => {
    const here = k * 6 + 6 <= flat.length;
    mark.point.visible = mark.arrow.visible = here && visible.contacts;
    if (!here) return;
    const p = V3(flat.slice(k * 6, k * 6 + 3));
    const f = V3(flat.slice(k * 6 + 3, k * 6 + 6));
    mark.point.position.copy(p);
    const length = (f.length() / weight) * 1.5 * scale;
    mark.arrow.visible = mark.arrow.visible && length > 1e-4;
    mark.arrow.position.copy(p);
    if (length > 1e-4) mark.arrow.setDirection(f.normalize());
    mark.arrow.setLength(Math.max(length, 1e-4), Math.min(0.1 * scale, 0.5 * length), 0.05 * scale);
  });

  // Layer switches.
  const shown = new Set((fragment.get('show') || '').split(','));
  const hidden = new Set((fragment.get('hide') || '').split(','));
  const applyLayers = []; // after the camera is placed, which looks at every layer
  for (const [name, objects] of Object.entries(layers)) {
    if (objects.length === 0) continue;
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.id = 'show-' + name;
    const byDefault = ['robot', 'contacts'].concat(S.visuals.length ? [] : ['endpoints']);
    box.checked = (byDefault.includes(name) || shown.has(name) || shown.has('all')) && !hidden.has(name);
    const apply = () => { visible[name] = box.checked; objects.forEach((o) => { o.visible = box.checked; }); };
    box.onchange = () => { apply(); if (T) placeAt(time); };
    applyLayers.push(apply);
    label.append(box, ' ' + { robot: 'robot', axes: 'joint axes', frames: 'body frames', com: 'centres of mass', inertia: 'inertia ellipsoids', endpoints: 'endpoints', contacts: 'contact forces' }[name]);
    $('layers').append(label);
  }

  // The body tree; a click (here or on the robot) outlines the body.
  let outline = null;
  const items = [];
  const select = (i) => {
    items.forEach((item, k) => item.classList.toggle('selected', k === i));
    if (outline) scene.remove(outline);
    outline = i === null ? null : new THREE.BoxHelper(frames[i], 0xff8f00);
    if (outline) scene.add(outline);
  };
  const lists = [$('tree')];
  S.bodies.forEach((b, i) => {
    const li = document.createElement('li');
    const name = document.createElement('span');
    name.textContent = b.name;
    name.title = `${b.joint_name}: ${b.joint.type}, ${b.mass.toPrecision(3)} kg`;
    name.onclick = () => select(i);
    items.push(name);
    const children = document.createElement('ul');
    li.append(name, children);
    (b.parent === null ? lists[0] : lists[b.parent + 1]).append(li);
    lists.push(children);
  });
  const pointer = new THREE.Vector2();
  renderer.domElement.addEventListener('click', (event) => {
    const r = renderer.domElement.getBoundingClientRect();
    pointer.set(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(pointer, camera);
    const hit = ray.intersectObjects(layers.robot, true)[0];
    let o = hit ? hit.object : null;
    while (o && !frames.includes(o)) o = o.parent;
    select(o ? frames.indexOf(o) : null);
  });

  // Joint sliders: each body's coordinates, composed along the parent array.
  const placements = S.bodies.map((b) => matrixOf(b.placement));
  const values = [];
  const jointMotion = (b, v) => {
    const m = new THREE.Matrix4();
    switch (b.joint.type) {
      case 'revolute': return m.makeRotationAxis(V3(b.joint.axis), v[0]);
      case 'prismatic': return m.makeTranslation(V3(b.joint.axis).multiplyScalar(v[0]));
      case 'free-flyer': return m.makeRotationFromEuler(new THREE.Euler(v[3], v[4], v[5], 'ZYX')).setPosition(v[0], v[1], v[2]);
      default: return m.makeRotationZ(v[2]).setPosition(v[0], v[1], 0);
    }
  };
  // A mimic joint's coordinate follows its leader's; its slider shows it.
  const followers = new Map(S.mimics.map((m) => [m.follower, m]));
  const syncSlider = [];
  const placeFromSliders = () => {
    S.mimics.forEach((m) => {
      values[m.follower][0] = m.multiplier * values[m.leader][0] + m.offset;
      if (syncSlider[m.follower]) syncSlider[m.follower]();
    });
    S.bodies.forEach((b, i) => {
      const parent = b.parent === null ? new THREE.Matrix4() : frames[b.parent].matrix;
      frames[i].matrix.multiplyMatrices(parent, placements[i]).multiply(jointMotion(b, values[i]));
      frames[i].matrixWorldNeedsUpdate = true;
    });
  };
  const startQ = (fragment.get('q') || '').split(',').filter((x) => x !== '').map(Number);
  const q0 = startQ.length === S.nq ? startQ : S.q;
  if (!T) {
    $('sliders').hidden = false;
    let k = 0;
    S.bodies.forEach((b, i) => {
      const q = q0.slice(k, k + b.nq);
      k += b.nq;
      const euler = b.joint.type === 'free-flyer'
        ? new THREE.Euler().setFromQuaternion(new THREE.Quaternion(q[3], q[4], q[5], q[6]).normalize(), 'ZYX') : null;
      // The URDF's limits, or a turn either way, or the robot's size.
      const turn = [-Math.PI, Math.PI];
      const length = [-size, size];
      const coords = {
        revolute: [['', q[0], b.limits || turn]], prismatic: [['', q[0], b.limits || length]],
        'free-flyer': [['x', q[0], length], ['y', q[1], length], ['z', q[2], length], ['roll', euler && euler.x, turn], ['pitch', euler && euler.y, turn], ['yaw', euler && euler.z, turn]],
        'planar-floating': [['x', q[0], length], ['y', q[1], length], ['θ', q[2], turn]],
      }[b.joint.type];
      values[i] = coords.map(([, v]) => v || 0);
      const leader = followers.get(i);
      coords.forEach(([what, , [lower, upper]], j) => {
        const label = document.createElement('label');
        const name = document.createElement('span');
        name.textContent = what ? `${b.joint_name} ${what}` : b.joint_name;
        if (leader) name.title = `follows ${S.bodies[leader.leader].joint_name} (× ${leader.multiplier} + ${leader.offset})`;
        const slider = document.createElement('input');
        // A start outside the limits widens the slider rather than move the
        // robot; its number turns red while outside.
        const v = values[i][j];
        Object.assign(slider, { type: 'range', min: Math.min(lower, v), max: Math.max(upper, v), step: (upper - lower) / 1000, value: v, disabled: !!leader });
        const shown = document.createElement('output');
        const show = () => {
          const x = values[i][j];
          shown.textContent = (Math.abs(x) < 0.005 ? 0 : x).toFixed(2);
          shown.classList.toggle('beyond', x < lower - 1e-9 || x > upper + 1e-9);
          shown.title = `${lower.toFixed(3)} to ${upper.toFixed(3)}` + (b.limits ? ' (URDF limits)' : '');
        };
        if (leader) syncSlider[i] = () => { slider.value = values[i][0]; show(); };
        slider.oninput = () => { values[i][j] = Number(slider.value); show(); placeFromSliders(); };
        show();
        label.append(name, slider, shown);
        $('sliders').append(label);
      });
    });
    placeFromSliders();
  }

  // Playback of a trajectory at real time.
  let playing = !!T && !fragment.has('t');
  let follow = false; // set once the camera is placed, for a floating base
  // The poses at time t: each body's between the samples around t, its
  // position lerped and its rotation slerped; contacts are the nearer
  // sample's (feet come and go between samples).
  const tween = { p: new THREE.Vector3(), q: new THREE.Quaternion(), p1: new THREE.Vector3(), q1: new THREE.Quaternion(), scale: new THREE.Vector3(), one: new THREE.Vector3(1, 1, 1) };
  function placeAt(t) {
    let lo = 0;
    let hi = T.t.length - 1;
    while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (T.t[mid] <= t) lo = mid; else hi = mid - 1; }
    const next = Math.min(lo + 1, T.t.length - 1);
    const span = T.t[next] - T.t[lo];
    const s = span > 0 ? THREE.MathUtils.clamp((t - T.t[lo]) / span, 0, 1) : 0;
    const nb = S.bodies.length;
    frames.forEach((g, i) => {
      g.matrix.copy(matrixOf(T.poses[lo], 12 * i));
      if (s > 0) {
        g.matrix.decompose(tween.p, tween.q, tween.scale);
        matrixOf(T.poses[next], 12 * i).decompose(tween.p1, tween.q1, tween.scale);
        g.matrix.compose(tween.p.lerp(tween.p1, s), tween.q.slerp(tween.q1, s), tween.one);
      }
      g.matrixWorldNeedsUpdate = true;
    });
    if (follow) { // the camera keeps its offset to a floating base
      const root = new THREE.Vector3().setFromMatrixPosition(frames[0].matrix);
      if (follow.isVector3) { camera.position.add(root.clone().sub(follow)); controls.target.add(root.clone().sub(follow)); }
      follow = root;
    }
    if (contactCount) showContacts(T.contacts[s < 0.5 ? lo : next]);
    $('time').value = end > 0 ? t / end : 0;
    const where = s > 0 ? `between samples ${lo + 1} and ${next + 1}` : `sample ${lo + 1}`;
    $('clock').textContent = `${t.toFixed(2)} s of ${end.toFixed(2)} s (${where} of ${T.t.length}, ${nb} bodies)`;
  }
  if (T) {
    $('motion').hidden = false;
    time = THREE.MathUtils.clamp(Number(fragment.get('t')) || 0, 0, end);
    $('play').textContent = playing ? 'Pause' : 'Play';
    $('play').onclick = () => { playing = !playing; $('play').textContent = playing ? 'Pause' : 'Play'; };
    $('time').oninput = () => { playing = false; $('play').textContent = 'Play'; time = Number($('time').value) * end; placeAt(time); };
    placeAt(time);
  }

  // Frame the robot and draw.
  $('name').textContent = S.name;
  $('summary').textContent = `${S.bodies.length} bodies, nq = ${S.nq}, ${S.bodies.reduce((s, b) => s + b.mass, 0).toFixed(3)} kg`
    + (S.meshes.length ? `, ${S.meshes.length} mesh files` : '') + (T ? `, ${T.t.length} samples` : '');
  scene.updateMatrixWorld(true);
  const box = new THREE.Box3();
  layers.robot.concat(layers.endpoints).forEach((o) => box.expandByObject(o));
  if (box.isEmpty()) box.setFromCenterAndSize(new THREE.Vector3(), new THREE.Vector3(1, 1, 1));
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  const travel = T ? Math.max(...T.poses.map((p) => Math.hypot(p[9], p[10], p[11]))) : 0;
  const grid = new THREE.GridHelper(Math.max(1, Math.ceil(4 * sphere.radius + 2 * travel)), 20, 0x999999, 0xdddddd);
  grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
  scene.add(grid);
  const side = Math.abs(up.z) > 0.9 ? new THREE.Vector3(1.3, -1.8, 0.9) : new THREE.Vector3(0.15, 0.25, 1);
  const aspect = Math.max(view.clientWidth, 1) / Math.max(view.clientHeight, 1);
  const halfAngle = Math.min(Math.atan(Math.tan(THREE.MathUtils.degToRad(20)) * aspect), THREE.MathUtils.degToRad(20));
  const distance = (sphere.radius / Math.sin(halfAngle)) * 1.1;
  camera.position.copy(sphere.center).addScaledVector(side.normalize(), distance);
  controls.target.copy(sphere.center);
  controls.update();
  applyLayers.forEach((apply) => apply());
  if (T) {
    scale = sphere.radius;
    follow = S.bodies.length > 0 && S.bodies[0].nq > 1;
    placeAt(time);
  }
  let last = null;
  function frame(now) {
    if (T && playing && last !== null) {
      time += (now - last) / 1000;
      if (time > end) time = 0;
      placeAt(time);
    }
    last = now;
    const w = view.clientWidth;
    const h = view.clientHeight;
    if (renderer.domElement.width !== Math.floor(w * renderer.getPixelRatio())) {
      renderer.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
    }
    if (outline) outline.update();
    renderer.render(scene, camera);
    if (document.body.dataset.status === 'loading') report('ready');
    requestAnimationFrame(frame);
  }
  frame(performance.now());
}
