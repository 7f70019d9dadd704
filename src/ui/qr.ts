/** QR codes (the share bar's and the printed worksheet's): the `qrcode` library, loaded on demand, to one SVG path. */

export interface QrPath {
  /** SVG path of the dark modules, offset by the four-module quiet zone. */
  d: string;
  /** Side of the code with its quiet zone, in modules (the SVG's viewBox). */
  size: number;
}

export async function qrPath(text: string): Promise<QrPath> {
  const QR = await import('qrcode');
  const create =
    (QR as unknown as { create?: typeof import('qrcode').create }).create ??
    (QR as unknown as { default: typeof import('qrcode') }).default.create;
  const code = create(text, { errorCorrectionLevel: 'M' });
  const { size, data } = code.modules as unknown as { size: number; data: Uint8Array };
  let d = '';
  for (let y = 0; y < size; y++)
    for (let x = 0; x < size; x++) if (data[y * size + x] === 1) d += `M${x + 4} ${y + 4}h1v1h-1z`;
  return { d, size: size + 8 };
}
