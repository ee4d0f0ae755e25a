package io.github.jdem846.projection;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The formula projections against independent values: hand-worked points on the unit sphere, and PROJ 9.1's
 * (GDAL 3.6.2, Debian) {@code gdaltransform -s_srs EPSG:4326 -t_srs "+proj=… +datum=WGS84 +units=m" -output_xy},
 * on a sphere of radius 6 378 137 m; and forward then inverse is the identity over the whole sphere.
 */
class SphericalFormulaTest {

    private static final double R = MapProjection.SPHERE_RADIUS;

    private static double[] forward(SphericalFormula f, double lonDeg, double latDeg) {
        double[] xy = new double[2];
        f.forward(Math.toRadians(lonDeg), Math.toRadians(latDeg), xy);
        return xy;
    }

    private static void assertProj(SphericalFormula f, double lon, double lat, double x, double y) {
        double[] xy = forward(f, lon, lat);
        assertEquals(x, xy[0] * R, 1e-3, f + " x at " + lon + ", " + lat);
        assertEquals(y, xy[1] * R, 1e-3, f + " y at " + lon + ", " + lat);
    }

    @Test
    void handWorkedPoints() {
        // Aitoff on the equator at λ = 90°: α = 45°, x = 2 sin 45° · (π/4) / sin 45° = π/2; at the pole y = π/2
        assertEquals(Math.PI / 2, forward(new Aitoff(), 90, 0)[0], 1e-15);
        assertEquals(Math.PI / 2, forward(new Aitoff(), 0, 90)[1], 1e-15);
        // Hammer at λ = 90°, φ = 0: x = 2√2 sin 45° / √(1 + cos 45°) = 2 / √(1 + √½); at λ = 180°: 2√2
        assertEquals(2 / Math.sqrt(1 + Math.sqrt(0.5)), forward(new Hammer(), 90, 0)[0], 1e-15);
        assertEquals(2 * Math.sqrt(2), forward(new Hammer(), 180, 0)[0], 1e-12);
        // Winkel Tripel on the equator: (λ cos φ₁ + λ) / 2, since Aitoff's x there is λ; cos φ₁ = 2/π
        assertEquals((Math.PI / 2 * 2 / Math.PI + Math.PI / 2) / 2, forward(new WinkelTripel(), 90, 0)[0], 1e-15);
        // Wagner VI at the pole: x = 0.94745 · π · √(1 − 3/4) at λ = 180°, y = 0.94745 · π/2
        assertEquals(0.94745 * Math.PI / 2, forward(new WagnerVI(), 180, 90)[0], 1e-15);
        assertEquals(0.94745 * Math.PI / 2, forward(new WagnerVI(), 0, 90)[1], 1e-15);
    }

    @Test
    void agreesWithProj() {
        assertProj(new Aitoff(), -84.2, 36.6, -7972465.74214512, 4415752.16460329);
        assertProj(new Aitoff(), 120, -30, 11918983.6619175, -3972994.5539725);
        assertProj(new Aitoff(), -179.5, -89.5, -174852.124886055, -10018129.846843);
        assertProj(new Hammer(), -84.2, 36.6, -7686616.33228565, 4257427.22585003);
        assertProj(new Hammer(), 10, 50, 789105.719897614, 5395052.27640258);
        assertProj(new Hammer(), -179.5, -89.5, -157423.039853383, -9019532.67747628);
        assertProj(new WagnerVI(), -84.2, 36.6, -8311576.2378535, 3860189.24680639);
        assertProj(new WagnerVI(), 120, -30, 12117540.41299, -3164089.54656261);
        assertProj(new WagnerVI(), -179.5, -89.5, -9621941.88488767, -9439533.81391179);
        // +proj=wintri +lat_1=50.4597762521898
        assertProj(new WinkelTripel(), -84.2, 36.6, -6969783.62329478, 4245022.76381855);
        assertProj(new WinkelTripel(), 180, 90, 6378137, 10018754.1713946);
        assertProj(new WinkelTripel(), 120, -30, 10211583.1642921, -3656289.63888535);
        assertProj(new WinkelTripel(), -179.5, -89.5, -6447846.01522081, -9990612.13642051);
    }

    @Test
    void inverseUndoesForwardOverTheSphereIncludingPolesAndAntimeridian() {
        double[] lats = {-90, -89.999999, -89.9, -75, -45, -10, -1e-9, 0, 1e-9, 10, 45, 60, 85, 89.9, 89.999999, 90};
        double[] lons = {-180, -179.999999, -179.9, -150, -90, -30, -1e-9, 0, 1e-9, 30, 90, 150, 179.9, 179.999999,
                180};
        for (SphericalFormula f : List.of(new Aitoff(), new Hammer(), new WinkelTripel(), new WagnerVI(),
                new WinkelTripel(50.467))) {
            for (double lat : lats) {
                for (double lon : lons) {
                    double[] xy = forward(f, lon, lat);
                    double[] back = new double[2];
                    f.inverse(xy[0], xy[1], back);
                    String at = f + " at " + lon + ", " + lat;
                    assertEquals(lat, Math.toDegrees(back[1]), 1e-9, at);
                    boolean poleIsAPoint = Math.abs(lat) == 90 && !(f instanceof WagnerVI);
                    if (!poleIsAPoint) {
                        // x and y hold λ to about 1e-16 / cos φ radians: the pole's neighbourhood is ill-conditioned
                        double tolerance = Math.max(1e-9, 1e-13 / Math.cos(Math.toRadians(lat)));
                        assertEquals(lon, Math.toDegrees(back[0]), tolerance, at);
                    }
                    double[] again = new double[2];
                    f.forward(back[0], back[1], again);
                    assertEquals(xy[0], again[0], 1e-9, at);
                    assertEquals(xy[1], again[1], 1e-9, at);
                }
            }
        }
    }

    @Test
    void pointsOffTheMapHaveNoInverse() {
        double[] out = new double[2];
        for (SphericalFormula f : List.of(new Aitoff(), new Hammer(), new WinkelTripel(), new WagnerVI())) {
            double[] corner = forward(f, 180, 0);
            double[] top = forward(f, 0, 90);
            f.inverse(corner[0] * 0.99, top[1] * 0.99, out); // near the corner of the bounding box
            assertTrue(Double.isNaN(out[0]) && Double.isNaN(out[1]), f + " gave " + out[0] + ", " + out[1]);
            f.inverse(corner[0] * 1.01, 0, out);
            assertTrue(Double.isNaN(out[0]), f + " beyond the equator's end");
        }
    }
}
