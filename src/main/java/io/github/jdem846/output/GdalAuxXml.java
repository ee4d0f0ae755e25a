package io.github.jdem846.output;

import io.github.jdem846.internal.SisLoggers;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.cs.AxisDirection;
import org.opengis.referencing.cs.CoordinateSystem;

/**
 * The GDAL "PAM" sidecar {@code <image>.aux.xml} holding the CRS, as {@code gdal_translate -of PNG} writes it.
 * GDAL (and so QGIS) takes the CRS of a PNG from this file; it does not read a {@code .prj} next to a PNG, which
 * only ESRI-style readers use.
 */
final class GdalAuxXml {

    static {
        SisLoggers.quiet(); // SIS's routine warnings off stderr, unless the application configured them
    }

    private GdalAuxXml() {
    }

    /**
     * The XML: a {@code <PAMDataset>} with one {@code <SRS>} element carrying {@code wkt}, and the mapping from the
     * image's (x = east, y = north) axes to the axes of {@code crs} (e.g. "2,1" for a latitude-first CRS).
     */
    static String of(String wkt, CoordinateReferenceSystem crs) {
        return "<PAMDataset>\n  <SRS dataAxisToSRSAxisMapping=\"" + axisMapping(crs) + "\">" + escape(wkt)
                + "</SRS>\n</PAMDataset>\n";
    }

    /** 1-based indices of the CRS axes pointing east–west and north–south; "1,2" when they cannot be found. */
    static String axisMapping(CoordinateReferenceSystem crs) {
        CoordinateSystem cs = crs.getCoordinateSystem();
        int x = -1;
        int y = -1;
        for (int i = 0; i < cs.getDimension(); i++) {
            AxisDirection d = cs.getAxis(i).getDirection();
            if (d == AxisDirection.EAST || d == AxisDirection.WEST) {
                x = i + 1;
            } else if (d == AxisDirection.NORTH || d == AxisDirection.SOUTH) {
                y = i + 1;
            }
        }
        return x > 0 && y > 0 && x != y ? x + "," + y : "1,2";
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
