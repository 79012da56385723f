// The course website: nothing yet beyond the theme (a placeholder keeps the build's file list
// stable); see website/build.py.
