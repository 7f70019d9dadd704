/**
 * Save bytes or text as a file: a temporary object URL clicked as a download link. The URL is
 * revoked after a while, not at once: some browsers start reading it after the click returns.
 */
export function downloadFile(name: string, data: BlobPart, type: string): void {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 30_000);
}
