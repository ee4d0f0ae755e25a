/**
 * The readers of the ESRI family behind {@code io.DemReader}: GridFloat, BIL, ASCII grid, their headers and
 * {@code .prj} files (ESRI WKT and the old ArcInfo keyword format). Internal: not exported by the module.
 */
package io.github.jdem846.io.esri;
