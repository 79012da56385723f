// The course website (website/build.py): a worked solution's code is the answer, so on the
// solution pages those cells start unfolded (still foldable); every other code cell starts
// folded, so that a page reads as a text first.
document.addEventListener("DOMContentLoaded", () => {
  for (const details of document.querySelectorAll(".tag_course-solution details.above-input")) {
    details.open = true;
  }
});
