package io.github.jdem846.projection;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The Winkel Tripel inverse (Newton's method with the analytic Jacobian, started from a neighbour's solution as the
 * warp does it, or from nothing): against PROJ 9.1's inverse ({@code gdaltransform -s_srs "+proj=wintri
 * +lat_1=50.4597762521898 +datum=WGS84 +units=m" -t_srs "+proj=longlat +datum=WGS84"}, GDAL 3.6.2), and
 * forward(inverse(x, y)) = (x, y) within 10⁻¹² on the unit sphere (6 µm on the Earth) over a dense scan of the
 * whole map, including the poles' lines and the meridians ±180°.
 */
class WinkelTripelInverseTest {

    private static final double R = MapProjection.SPHERE_RADIUS;
    private static final WinkelTripel WINKEL = new WinkelTripel();

    @Test
    void agreesWithProjsInverse() {
        double[][] cases = { // x, y in metres; longitude, latitude in degrees, as PROJ gives them
            {-6969783.62329478, 4245022.76381855, -84.2, 36.6},
            {10211583.1642921, -3656289.63888535, 120, -30},
            {-6447846.01522081, -9990612.13642051, -179.5, -89.5},
            {1000000, 9000000, 20.7861026713329, 80.7894818598597},
            {-16000000, 1000000, -176.449968655468, 7.08210228728089},
            {15000000, 3000000, 171.881646525071, 21.8024499974941},
            {3000000, -9500000, 70.8080892801316, -84.9266536671704},
        };
        double[] lp = new double[2];
        for (double[] c : cases) {
            WINKEL.inverse(c[0] / R, c[1] / R, lp);
            assertEquals(c[2], Math.toDegrees(lp[0]), 1e-9, "longitude at " + c[0] + ", " + c[1]);
            assertEquals(c[3], Math.toDegrees(lp[1]), 1e-9, "latitude at " + c[0] + ", " + c[1]);
        }
    }

    /** A scan of the map's bounding box row by row, each point started from the two before it as the warp does. */
    @Test
    void roundTripOverTheWholeMapWithAndWithoutNeighbours() {
        double halfWidth = (Math.PI * 2 / Math.PI + Math.PI) / 2;
        int cols = 1201;
        int rows = 601;
        double[] lp = new double[2];
        double[] xy = new double[2];
        double worst = 0;
        int onMap = 0;
        for (int r = 0; r < rows; r++) {
            double y = Math.PI / 2 - Math.PI * r / (rows - 1); // both poles' lines included
            double[] last = {Double.NaN, Double.NaN};
            double[] previous = {Double.NaN, Double.NaN};
            for (int c = 0; c < cols; c++) {
                double x = -halfWidth + 2 * halfWidth * c / (cols - 1); // ±180° at the equator included
                double[] hint = Double.isNaN(previous[0]) ? last.clone()
                        : new double[] {2 * last[0] - previous[0], 2 * last[1] - previous[1]};
                WINKEL.inverse(x, y, hint, lp);
                boolean inside = WinkelTripel.onMap(x, y, 2 / Math.PI);
                assertEquals(inside, !Double.isNaN(lp[0]), "found a solution at " + x + ", " + y);
                if (inside) {
                    onMap++;
                    assertTrue(Math.abs(lp[0]) <= Math.PI && Math.abs(lp[1]) <= Math.PI / 2);
                    WINKEL.forward(lp[0], lp[1], xy);
                    worst = Math.max(worst, Math.max(Math.abs(xy[0] - x), Math.abs(xy[1] - y)));
                    double[] cold = new double[2];
                    WINKEL.inverse(x, y, cold); // without a neighbour: the same point
                    assertEquals(lp[1], cold[1], 1e-12, "latitude at " + x + ", " + y);
                    if (Math.abs(lp[1]) < Math.PI / 2 - 1e-6) {
                        assertEquals(lp[0], cold[0], 1e-10, "longitude at " + x + ", " + y);
                    }
                }
                previous = last;
                last = lp.clone();
            }
        }
        assertTrue(worst <= 1e-12, "forward(inverse(p)) is " + worst + " from p");
        // the map fills about four fifths of its bounding box: the scan must have covered it
        assertTrue(onMap > 0.7 * cols * rows && onMap < 0.9 * cols * rows, onMap + " points on the map");
    }

    @Test
    void theOutlineIsTheMeridiansOf180Degrees() {
        double[] edge = new double[2];
        double[] lp = new double[2];
        for (double lat = -90; lat <= 90; lat += 0.5) {
            for (double sign : new double[] {-1, 1}) {
                WINKEL.forward(sign * Math.PI, Math.toRadians(lat), edge);
                assertTrue(WinkelTripel.onMap(edge[0] * (1 - 1e-7), edge[1], 2 / Math.PI), "inside at " + lat);
                assertFalse(WinkelTripel.onMap(edge[0] + sign * 1e-7, edge[1], 2 / Math.PI), "outside at " + lat);
                WINKEL.inverse(edge[0], edge[1], lp);
                assertEquals(lat, Math.toDegrees(lp[1]), 1e-9, "latitude of the edge at " + lat);
                if (Math.abs(lat) < 90) {
                    assertEquals(sign * 180, Math.toDegrees(lp[0]), 1e-7, "longitude of the edge at " + lat);
                }
                WINKEL.inverse(edge[0] + sign * 1e-7, edge[1], lp);
                assertTrue(Double.isNaN(lp[0]), "just outside the edge at " + lat);
            }
        }
    }

    @Test
    void aFarHintStillGivesTheSolution() {
        double[] xy = new double[2];
        double[] lp = new double[2];
        WINKEL.forward(Math.toRadians(150), Math.toRadians(-60), xy);
        WINKEL.inverse(xy[0], xy[1], new double[] {Math.toRadians(-170), Math.toRadians(85)}, lp);
        assertEquals(150, Math.toDegrees(lp[0]), 1e-9);
        assertEquals(-60, Math.toDegrees(lp[1]), 1e-9);
    }
}
