// Appended by review_browser_test.sh to a copy of the review page (never part of the report): once the page has
// loaded, lists each image of a failing case as "<case id> <role> <width>x<height> whole|partial|empty" in the pre
// element "image-check". Drawn on a canvas, a fully decoded image has its last pixel opaque; a truncated one
// does not.
window.addEventListener("load", () => {
  const lines = [...document.querySelectorAll("section.failure img")].map((img) => {
    let whole = "empty";
    if (img.naturalWidth > 0) {
      const canvas = document.createElement("canvas");
      canvas.width = img.naturalWidth;
      canvas.height = img.naturalHeight;
      const g = canvas.getContext("2d");
      g.drawImage(img, 0, 0);
      const alpha = g.getImageData(img.naturalWidth - 1, img.naturalHeight - 1, 1, 1).data[3];
      whole = alpha === 255 ? "whole" : "partial";
    }
    return `${img.closest("section").id} ${img.className} ${img.naturalWidth}x${img.naturalHeight} ${whole}`;
  });
  const pre = document.createElement("pre");
  pre.id = "image-check";
  pre.textContent = lines.join("\n");
  document.body.appendChild(pre);
});
