package io.github.jdem846.io.esri;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.source.ReaderGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.util.List;

/**
 * The grid size and outer-corner georeferencing an ESRI header gives, whichever of its equivalent keys it uses:
 * {@code xllcorner}/{@code yllcorner} (outer lower-left corner), {@code xllcenter}/{@code yllcenter} (centre of
 * the lower-left cell) or {@code ulxmap}/{@code ulymap} (centre of the upper-left cell, BIL style); cell size from
 * {@code cellsize}, or {@code xdim}/{@code ydim}, or {@code dx}/{@code dy}.
 *
 * @param cols       columns
 * @param rows       rows
 * @param originX    x of the west edge
 * @param originY    y of the north edge
 * @param cellWidth  cell width
 * @param cellHeight cell height
 * @param anchor     what the header anchored on
 */
public record EsriGridLayout(int cols, int rows, double originX, double originY, double cellWidth, double cellHeight,
                      PixelAnchor anchor) {

    /**
     * Resolves the layout.
     *
     * @param h             the header
     * @param bilDefaults   true for BIL, whose keys are optional with ESRI's defaults (xdim = ydim = 1, ulxmap =
     *                      0, ulymap = nrows − 1); a notice is added when they are used
     * @param notices       where to add notices
     */
    static EsriGridLayout of(EsriHeader h, boolean bilDefaults, List<String> notices) throws DemFormatException {
        int cols = h.positiveInt("ncols");
        int rows = h.positiveInt("nrows");
        double cw;
        double ch;
        String cellKeyX = null; // null: ESRI's default
        String cellKeyY = null;
        if (h.has("cellsize")) {
            cw = h.positive("cellsize");
            ch = cw;
            cellKeyX = "cellsize";
            cellKeyY = "cellsize";
        } else if (h.has("xdim") || h.has("ydim")) {
            cw = h.positive("xdim");
            ch = h.positive("ydim");
            cellKeyX = "xdim";
            cellKeyY = "ydim";
        } else if (h.has("dx") || h.has("dy")) {
            cw = h.positive("dx");
            ch = h.positive("dy");
            cellKeyX = "dx";
            cellKeyY = "dy";
        } else if (bilDefaults) {
            cw = 1;
            ch = 1;
            notices.add("no XDIM/YDIM in the header: cells taken as 1 × 1 unit (ESRI's default)");
        } else {
            throw new DemFormatException(h.file(), "header key 'cellsize' is missing (or give 'xdim' and 'ydim')");
        }

        PixelAnchor anchor = PixelAnchor.CORNER;
        double originX;
        String xKey = h.firstPresent("xllcorner", "xllcenter", "ulxmap").orElse(null);
        if (xKey == null) {
            if (!bilDefaults) {
                throw new DemFormatException(h.file(), "header key 'xllcorner' is missing (or give 'xllcenter')");
            }
            originX = -cw / 2;
            anchor = PixelAnchor.CENTER;
            notices.add("no ULXMAP in the header: placed at x = 0 (ESRI's default)");
        } else {
            double x = h.finite(xKey);
            if (xKey.equals("xllcorner")) {
                originX = x;
            } else {
                originX = x - cw / 2;
                anchor = PixelAnchor.CENTER;
            }
        }

        double originY;
        double southY; // for the check below: from the key itself where it names the south edge
        String yKey = h.firstPresent("yllcorner", "yllcenter", "ulymap").orElse(null);
        if (yKey == null) {
            if (!bilDefaults) {
                throw new DemFormatException(h.file(), "header key 'yllcorner' is missing (or give 'yllcenter')");
            }
            originY = (rows - 1) * ch + ch / 2;
            southY = originY - rows * ch;
            anchor = PixelAnchor.CENTER;
            notices.add("no ULYMAP in the header: placed at y = nrows − 1 (ESRI's default)");
        } else {
            double y = h.finite(yKey);
            originY = switch (yKey) {
                case "yllcorner" -> y + rows * ch;
                case "yllcenter" -> y - ch / 2 + rows * ch;
                default -> y + ch / 2; // ulymap: centre of the upper-left cell
            };
            southY = switch (yKey) {
                case "yllcorner" -> y;
                case "yllcenter" -> y - ch / 2;
                default -> originY - rows * ch;
            };
            if (!yKey.equals("yllcorner")) {
                anchor = PixelAnchor.CENTER;
            }
        }
        // each key can be sane and the grid still not: 1e308 × nrows overflows, 1e-300 cells at 500000 collapse
        ReaderGeometry.checkEdges(h.file(), keys(xKey, "ncols", cellKeyX), keys(yKey, "nrows", cellKeyY), originX,
                originX + cols * cw, southY, originY, cw, ch);
        return new EsriGridLayout(cols, rows, originX, originY, cw, ch, anchor);
    }

    /** "header keys 'xllcorner', 'ncols' and 'cellsize'", leaving out keys the header does not have. */
    private static String keys(String... keys) {
        java.util.List<String> present = new java.util.ArrayList<>();
        for (String k : keys) {
            if (k != null) {
                present.add("'" + k + "'");
            }
        }
        int last = present.size() - 1;
        String list = last == 0 ? present.get(0)
                : String.join(", ", present.subList(0, last)) + " and " + present.get(last);
        return "header key" + (last == 0 ? " " : "s ") + list;
    }
}
