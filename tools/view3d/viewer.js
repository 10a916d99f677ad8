// The report's 3-D view (tools/view3d.py writes its data): the formed fabric and the bodies,
// turned, zoomed and panned with the mouse (three.js's OrbitControls), coloured by the field
// chosen, a colour bar in its units, a node read by clicking it, the frames (load steps) played.
// The address may open it on a field, frame and node: report.html#field=strain_weft&frame=3&node=120
// (frame 1 is the first), and `&alone` shows the view without the rest of the report. What it shows is also in the DOM, for a browser test: #view3d's
// data-state ("ready", or why there is no view), data-field, data-frame and data-first-frame-ms;
// #view3d-pick's data-node and data-values (JSON: the node's position and fields in the files' SI units).
(function () {
  "use strict";
  const root = document.getElementById("view3d");
  const message = document.getElementById("view3d-message");
  const canvasBox = document.getElementById("view3d-canvas");
  const grey = [0.72, 0.72, 0.74];

  function stop(state, text) {
    root.dataset.state = state;
    message.textContent = text;
    return null;
  }

  function webglAvailable() {
    try {
      const canvas = document.createElement("canvas");
      return !!(window.WebGLRenderingContext && (canvas.getContext("webgl") || canvas.getContext("experimental-webgl")));
    } catch (e) {
      return false;
    }
  }

  // base64 → bytes without a callback per character (a large run holds tens of megabytes).
  function buffer(text) {
    const chars = atob(text);
    const bytes = new Uint8Array(chars.length);
    for (let i = 0; i < chars.length; ++i) bytes[i] = chars.charCodeAt(i);
    return bytes.buffer;
  }
  const floats = (text) => new Float32Array(buffer(text));
  const indices = (text) => new Uint32Array(buffer(text));

  // matplotlib's viridis at nine stops, as the report's pictures use it.
  const VIRIDIS = [[0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207, 0.372, 0.553],
                   [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267, 0.749, 0.441],
                   [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144]];
  function colour(t, out, at) {
    const x = Math.min(Math.max(Number.isFinite(t) ? t : 0, 0), 1) * (VIRIDIS.length - 1);
    const k = Math.min(Math.floor(x), VIRIDIS.length - 2), f = x - k;
    for (let c = 0; c < 3; ++c) out[at + c] = VIRIDIS[k][c] * (1 - f) + VIRIDIS[k + 1][c] * f;
  }

  function start(data) {
    const started = performance.now();
    const triangles = indices(data.triangles);
    const cellOf = indices(data.triangle_cell);
    const bodyTriangles = indices(data.body_triangles);
    const fields = new Map(data.fields.map((f) => [f.name, f]));
    const decoded = new Map();  // frame index → its arrays, decoded when first shown
    function frame(k) {
      if (!decoded.has(k)) {
        const f = data.frames[k];
        const values = {};
        for (const name of Object.keys(f.fields)) values[name] = floats(f.fields[name]);
        decoded.set(k, {label: f.label, points: floats(f.buffers.points),
                        bodies: f.buffers.bodies ? floats(f.buffers.bodies) : null, values: values});
      }
      return decoded.get(k);
    }

    const renderer = new THREE.WebGLRenderer({antialias: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    canvasBox.replaceChildren(renderer.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf4f4f4);
    const camera = new THREE.PerspectiveCamera(35, 1, 1e-4, 100);
    camera.up.set(0, 0, 1);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const light = new THREE.DirectionalLight(0xffffff, 0.6);
    camera.add(light);
    scene.add(camera);

    const corners = triangles.length;
    const fabricGeometry = new THREE.BufferGeometry();
    fabricGeometry.setAttribute("position", new THREE.BufferAttribute(new Float32Array(3 * corners), 3));
    fabricGeometry.setAttribute("color", new THREE.BufferAttribute(new Float32Array(3 * corners), 3));
    const fabric = new THREE.Mesh(fabricGeometry, new THREE.MeshLambertMaterial(
        {vertexColors: THREE.VertexColors, side: THREE.DoubleSide}));
    scene.add(fabric);
    let bodies = null;
    const shownFirst = frame(data.frames.length - 1);
    if (bodyTriangles.length > 0 && shownFirst.bodies) {
      const g = new THREE.BufferGeometry();
      const count = shownFirst.bodies.length;
      g.setIndex(new THREE.BufferAttribute(bodyTriangles, 1));
      g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(count), 3));
      g.setAttribute("color", new THREE.BufferAttribute(new Float32Array(count), 3));
      // Pushed back a little in depth: the fabric lying on a face is drawn over it, not through it.
      bodies = new THREE.Mesh(g, new THREE.MeshLambertMaterial({vertexColors: THREE.VertexColors, side: THREE.DoubleSide,
                                                                 polygonOffset: true, polygonOffsetFactor: 2,
                                                                 polygonOffsetUnits: 2}));
      scene.add(bodies);
    }
    const marker = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 16, 12), new THREE.MeshBasicMaterial({color: 0xd00000}));
    marker.visible = false;
    scene.add(marker);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    const render = () => renderer.render(scene, camera);
    controls.addEventListener("change", render);

    const view = {frame: data.frames.length - 1, field: data.fields.length ? data.fields[0].name : null};

    function placeFabric(points) {
      const position = fabricGeometry.attributes.position.array;
      for (let c = 0; c < corners; ++c) {
        const n = triangles[c];
        position[3 * c] = points[3 * n];
        position[3 * c + 1] = points[3 * n + 1];
        position[3 * c + 2] = points[3 * n + 2];
      }
      fabricGeometry.attributes.position.needsUpdate = true;
      fabricGeometry.computeVertexNormals();
      fabricGeometry.computeBoundingSphere();
    }

    function placeBodies(points) {
      if (!bodies || !points) return;
      bodies.geometry.attributes.position.array.set(points);
      bodies.geometry.attributes.position.needsUpdate = true;
      bodies.geometry.computeVertexNormals();
      bodies.geometry.computeBoundingSphere();
    }

    function paint() {
      const f = frame(view.frame);
      const field = fields.get(view.field);
      const values = field ? f.values[field.name] : undefined;
      const span = field && field.high > field.low ? field.high - field.low : 1;
      const fabricColour = fabricGeometry.attributes.color.array;
      for (let c = 0; c < corners; ++c) {
        if (values && field.where === "node") colour((values[triangles[c]] - field.low) / span, fabricColour, 3 * c);
        else if (values && field.where === "cell") colour((values[cellOf[Math.floor(c / 3)]] - field.low) / span, fabricColour, 3 * c);
        else fabricColour.set(grey, 3 * c);
      }
      fabricGeometry.attributes.color.needsUpdate = true;
      if (bodies) {
        const bodyColour = bodies.geometry.attributes.color.array;
        for (let v = 0; v < bodyColour.length / 3; ++v) {
          if (values && field.where === "body") colour((values[v] - field.low) / span, bodyColour, 3 * v);
          else bodyColour.set(grey, 3 * v);
        }
        bodies.geometry.attributes.color.needsUpdate = true;
      }
      legend(field, values !== undefined);
      root.dataset.field = view.field || "";
    }

    function legend(field, present) {
      const box = document.getElementById("view3d-legend");
      box.replaceChildren();
      if (!field) return;
      const unit = field.unit ? " (" + field.unit + ")" : "";
      if (!present) {
        box.textContent = field.label + unit + ": not written for " + frame(view.frame).label +
            (field.where === "cell" ? " (per-cell fields are the final state's)" : "");
        box.className = "view3d-legend missing";
        return;
      }
      box.className = "view3d-legend";
      const bar = document.createElement("span");
      const stops = VIRIDIS.map((c, k) => "rgb(" + c.map((x) => Math.round(255 * x)).join(",") + ") " +
                                          (100 * k / (VIRIDIS.length - 1)).toFixed(0) + "%");
      bar.style.cssText = "display:inline-block;width:16em;height:1em;vertical-align:middle;margin:0 0.5em;" +
                          "background:linear-gradient(to right," + stops.join(",") + ")";
      const low = document.createElement("span"), high = document.createElement("span");
      // Beyond the bar's ends the colours saturate; the ends say so where values go further.
      low.textContent = (field.min < field.low ? "≤ " : "") + format(field.low * field.factor);
      high.textContent = (field.max > field.high ? "≥ " : "") + format(field.high * field.factor) + unit +
                         (field.max > field.high || field.min < field.low
                              ? " (all: " + format(field.min * field.factor) + " to " + format(field.max * field.factor) + ")"
                              : "");
      const what = document.createElement("strong");
      what.textContent = field.label + ": ";
      box.append(what, low, bar, high);
    }

    function format(x) {
      return Math.abs(x) >= 1e4 || (Math.abs(x) < 1e-3 && x !== 0) ? x.toExponential(3) : x.toPrecision(4);
    }

    function showFrame(k) {
      view.frame = Math.min(Math.max(k, 0), data.frames.length - 1);
      const f = frame(view.frame);
      placeFabric(f.points);
      placeBodies(f.bodies);
      paint();
      document.getElementById("view3d-step").value = view.frame;
      document.getElementById("view3d-frame").textContent = f.label + " (frame " + (view.frame + 1) + " of " +
                                                             data.frames.length + ")";
      root.dataset.frame = view.frame + 1;
      render();
    }

    function frameCamera() {
      fabricGeometry.computeBoundingSphere();
      const sphere = fabricGeometry.boundingSphere;
      const r = sphere.radius > 0 ? sphere.radius : 1;
      controls.target.copy(sphere.center);
      camera.near = r / 100;
      camera.far = r * 100;
      camera.position.copy(sphere.center).add(new THREE.Vector3(1.2, -1.6, 1.3).normalize().multiplyScalar(2.5 * r));
      camera.updateProjectionMatrix();
      controls.update();
    }

    function resize() {
      const width = canvasBox.clientWidth || 800, height = canvasBox.clientHeight || 500;
      renderer.setSize(width, height);
      camera.aspect = width / height;
      camera.updateProjectionMatrix();
      render();
    }

    // The node nearest the point where a ray from the screen meets the fabric.
    const raycaster = new THREE.Raycaster();
    function pickAt(clientX, clientY) {
      const box = renderer.domElement.getBoundingClientRect();
      const ndc = new THREE.Vector2(2 * (clientX - box.left) / box.width - 1, 1 - 2 * (clientY - box.top) / box.height);
      raycaster.setFromCamera(ndc, camera);
      const hit = raycaster.intersectObject(fabric)[0];
      if (!hit) return null;
      const t = hit.faceIndex;
      const points = frame(view.frame).points;
      let best = -1, bestDistance = Infinity;
      for (let c = 0; c < 3; ++c) {
        const n = triangles[3 * t + c];
        const d = hit.point.distanceToSquared(new THREE.Vector3(points[3 * n], points[3 * n + 1], points[3 * n + 2]));
        if (d < bestDistance) best = n, bestDistance = d;
      }
      showNode(best, cellOf[t]);
      return best;
    }

    function showNode(node, cell) {
      const f = frame(view.frame);
      const position = [f.points[3 * node], f.points[3 * node + 1], f.points[3 * node + 2]];
      const raw = {position_m: position};
      const rows = [["node", String(node)], ["position (mm)", position.map((x) => (1000 * x).toFixed(3)).join(", ")]];
      for (const field of data.fields) {
        const values = f.values[field.name];
        if (!values || field.where === "body") continue;
        const at = field.where === "node" ? node : cell;
        raw[field.name] = values[at];
        rows.push([field.label + (field.where === "cell" ? " (its cell " + cell + ")" : ""),
                   format(values[at] * field.factor) + (field.unit ? " " + field.unit : "")]);
      }
      const box = document.getElementById("view3d-pick");
      const table = document.createElement("table");
      for (const [name, value] of rows) {
        const tr = table.insertRow();
        const th = document.createElement("th");
        th.textContent = name;
        tr.append(th);
        tr.insertCell().textContent = value;
      }
      box.replaceChildren(table);
      marker.position.set(position[0], position[1], position[2]);
      marker.scale.setScalar(fabricGeometry.boundingSphere.radius / 150);
      marker.visible = true;
      render();
      box.dataset.node = node;
      box.dataset.values = JSON.stringify(raw);
    }

    // Picks the node where it shows on the screen, as a click there would.
    function pickNode(node) {
      const points = frame(view.frame).points;
      const p = new THREE.Vector3(points[3 * node], points[3 * node + 1], points[3 * node + 2]).project(camera);
      const box = renderer.domElement.getBoundingClientRect();
      return pickAt(box.left + (p.x + 1) / 2 * box.width, box.top + (1 - p.y) / 2 * box.height);
    }

    const select = document.getElementById("view3d-field");
    for (const field of data.fields) {
      const option = document.createElement("option");
      option.value = field.name;
      option.textContent = field.label + (field.unit ? " (" + field.unit + ")" : "");
      select.append(option);
    }
    select.addEventListener("change", () => { view.field = select.value; paint(); render(); });
    const slider = document.getElementById("view3d-step");
    slider.max = data.frames.length - 1;
    slider.addEventListener("input", () => showFrame(Number(slider.value)));
    if (data.frames.length < 2) document.getElementById("view3d-steps").hidden = true;
    let playing = null;
    document.getElementById("view3d-play").addEventListener("click", () => {
      if (playing) return clearInterval(playing), playing = null;
      if (view.frame === data.frames.length - 1) showFrame(0);
      playing = setInterval(() => {
        if (view.frame >= data.frames.length - 1) return clearInterval(playing), playing = null;
        showFrame(view.frame + 1);
      }, 700);
    });
    let down = null;
    renderer.domElement.addEventListener("pointerdown", (e) => { down = [e.clientX, e.clientY]; });
    renderer.domElement.addEventListener("pointerup", (e) => {
      if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) pickAt(e.clientX, e.clientY);
      down = null;
    });
    window.addEventListener("resize", resize);

    const asked = new URLSearchParams(window.location.hash.slice(1));
    if (asked.has("alone")) document.body.replaceChildren(root);  // the view without the report round it
    showFrame(view.frame);
    frameCamera();
    resize();
    if (asked.has("field") && fields.has(asked.get("field"))) {
      view.field = select.value = asked.get("field");
      paint();
    }
    if (asked.has("frame")) showFrame(Number(asked.get("frame")) - 1);
    else render();
    if (asked.has("node")) pickNode(Number(asked.get("node")));
    renderer.getContext().finish();
    root.dataset.firstFrameMs = (performance.now() - started).toFixed(0);
    root.dataset.loadedMs = performance.now().toFixed(0);
    root.dataset.state = "ready";
    window.fabformView = {showFrame: showFrame, pickNode: pickNode, pickAt: pickAt};
  }

  if (!window.FABFORM_VIEW) stop("no-data", "view3d/data.js is missing, so there is nothing to turn; the pictures below show the results.");
  else if (typeof THREE === "undefined" || !THREE.OrbitControls)
    stop("no-library", "view3d/three.min.js or OrbitControls.js is missing; the pictures below show the results.");
  else if (!webglAvailable()) stop("no-webgl", "WebGL is unavailable in this browser; the pictures below show the results.");
  else start(window.FABFORM_VIEW);
})();
