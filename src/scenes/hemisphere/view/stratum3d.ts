/**
 * The followed stratum in the 3D view: the cell's patch (a translucent mesh) and its outline,
 * morphed from the square to the hemisphere with the points, and the points' shader marking the
 * cell's samples (drawn larger, full colour) against the others (faded towards the background).
 * Colours follow the page's theme (the `data-theme` attribute of the document).
 */
import type * as THREE from 'three';
import type { ViewportContext } from '../../../three';
import type { Lobe } from '../lobe';
import { cellBounds, cellOutline, cellPatch, morphVertices, type Cell } from '../stratum';

/**
 * The uniforms the points' shader reads: the cell's ξ ranges (ξ₁ from, to, ξ₂ from, to; a first
 * entry below 0: none) and the fade colour.
 */
export interface StratumUniforms {
  uCell: { value: Float32Array };
  uFade: { value: THREE.Color };
}

/** Theme colours: the outline in the text colour, the fade towards the viewport's background. */
function themeColours(): { line: number; fade: number } {
  const dark = document.documentElement.dataset.theme === 'dark';
  return dark ? { line: 0xeceff4, fade: 0x111317 } : { line: 0x1c1d21, fade: 0xeceae3 };
}

export function stratumUniforms(T: ViewportContext['THREE']): StratumUniforms {
  return {
    uCell: { value: new Float32Array([-1, -1, -1, -1]) },
    uFade: { value: new T.Color(themeColours().fade) },
  };
}

/**
 * Add the stratum to the points' shader (after the morph): a point whose (ξ₁, ξ₂) lies in the cell
 * is drawn 1.8 times larger, the others fade 70 % towards the background.
 */
export function patchStratumShader(
  shader: { uniforms: Record<string, unknown>; vertexShader: string; fragmentShader: string },
  u: StratumUniforms,
): void {
  shader.uniforms.uCell = u.uCell;
  shader.uniforms.uFade = u.uFade;
  shader.vertexShader = shader.vertexShader
    .replace('#include <common>', '#include <common>\nuniform vec4 uCell;\nvarying float vStratum;')
    .replace(
      'gl_PointSize = size;',
      [
        'vStratum = uCell.x < 0.0 ? -1.0 : ',
        '  (xi.x >= uCell.x && xi.x < uCell.y && xi.y >= uCell.z && xi.y < uCell.w ? 1.0 : 0.0);',
        'gl_PointSize = size * (vStratum > 0.5 ? 1.8 : 1.0);',
      ].join('\n'),
    );
  shader.fragmentShader = shader.fragmentShader
    .replace('#include <common>', '#include <common>\nuniform vec3 uFade;\nvarying float vStratum;')
    .replace(
      '#include <color_fragment>',
      '#include <color_fragment>\nif (vStratum > -0.5 && vStratum < 0.5) diffuseColor.rgb = mix(diffuseColor.rgb, uFade, 0.7);',
    );
}

export interface StratumLayer {
  /** Show this cell of this lobe (null: none); rebuilds the patch and the outline. */
  set: (lobe: Lobe, cell: Cell | null) => void;
  /** Move the patch and the outline to morph fraction s. */
  morph: (s: number) => void;
  dispose: () => void;
}

export function stratumLayer(ctx: ViewportContext, u: StratumUniforms): StratumLayer {
  const T = ctx.THREE;
  const lineMat = new T.LineBasicMaterial({ color: themeColours().line });
  const fillMat = new T.MeshBasicMaterial({
    color: themeColours().line,
    transparent: true,
    opacity: 0.22,
    depthWrite: false,
    side: T.DoubleSide,
  });
  let outline: { obj: THREE.LineLoop; a: Float64Array; b: Float64Array } | null = null;
  let patch: { obj: THREE.Mesh; a: Float64Array; b: Float64Array } | null = null;
  let s = 0;

  const clear = () => {
    for (const o of [outline?.obj, patch?.obj]) {
      if (!o) continue;
      ctx.scene.remove(o);
      o.geometry.dispose();
    }
    outline = null;
    patch = null;
  };
  const recolour = () => {
    const c = themeColours();
    lineMat.color.setHex(c.line);
    fillMat.color.setHex(c.line);
    u.uFade.value.setHex(c.fade);
    ctx.invalidate();
  };
  const themeWatch = new MutationObserver(recolour);
  themeWatch.observe(document.documentElement, { attributes: true, attributeFilter: ['data-theme'] });

  const morph = (next: number) => {
    s = next;
    for (const part of [outline, patch]) {
      if (!part) continue;
      const attr = part.obj.geometry.getAttribute('position') as THREE.BufferAttribute;
      morphVertices(part.a, part.b, s, attr.array as Float32Array);
      attr.needsUpdate = true;
    }
  };

  const lifted = (b: Float64Array, f: number) => b.map((x) => x * f);

  return {
    set(lobe, cell) {
      clear();
      if (!cell) {
        u.uCell.value.set([-1, -1, -1, -1]);
        ctx.invalidate();
        return;
      }
      const { xi1, xi2 } = cellBounds(cell);
      u.uCell.value.set([xi1[0], xi1[1], xi2[0], xi2[1]]);
      // just above the shell and the grid, so neither hides them
      const o = cellOutline(lobe, cell, 24);
      const og = new T.BufferGeometry();
      og.setAttribute('position', new T.BufferAttribute(new Float32Array(o.a.length), 3));
      outline = { obj: new T.LineLoop(og, lineMat), a: o.a, b: lifted(o.b, 1.006) };
      const p = cellPatch(lobe, cell, 12);
      const pg = new T.BufferGeometry();
      pg.setAttribute('position', new T.BufferAttribute(new Float32Array(p.a.length), 3));
      pg.setIndex(new T.BufferAttribute(p.index, 1));
      patch = { obj: new T.Mesh(pg, fillMat), a: p.a, b: lifted(p.b, 1.004) };
      for (const part of [outline, patch]) {
        part.obj.frustumCulled = false;
        ctx.scene.add(part.obj);
      }
      recolour();
      morph(s);
    },
    morph,
    dispose() {
      themeWatch.disconnect();
      clear();
      lineMat.dispose();
      fillMat.dispose();
    },
  };
}
