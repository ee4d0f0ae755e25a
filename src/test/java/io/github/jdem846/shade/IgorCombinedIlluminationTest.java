package io.github.jdem846.shade;

import static io.github.jdem846.shade.ShadeTestSupport.illuminate;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.SyntheticDems;
import org.junit.jupiter.api.Test;

/**
 * gdaldem's {@code -igor} and {@code -combined} on planes, worked out by hand from their definitions (the bytes of
 * real DEMs against gdaldem are in {@link GdaldemGoldenTest}).
 */
class IgorCombinedIlluminationTest {

    private static final HillshadeOptions D = HillshadeOptions.DEFAULTS;

    /** 7 × 6 cells of 10 m rising 1 m per metre eastward: a 45° slope that faces west, downslope toward the west. */
    private static final Dem WEST_FACING = SyntheticDems.surface(7, 6, 10, (x, y) -> x);

    /** The value of an inner cell (edge cells follow gdaldem's extrapolation, tested for Horn elsewhere). */
    private static float inner(HillshadeMethod method, Dem dem, double az, double alt, HillshadeOptions options) {
        float[] out = illuminate(method.stage(options), dem, new LightDirection(az, alt));
        return out[3 * dem.width() + 3];
    }

    @Test
    void stagesAreTheDocumentedClasses() {
        assertInstanceOf(IgorIllumination.class, HillshadeMethod.IGOR.stage(D));
        assertInstanceOf(CombinedIllumination.class, HillshadeMethod.COMBINED.stage(D));
    }

    @Test
    void igorDarkensASlopeByHowFarItFacesAwayFromTheLight() {
        // slope strength 45/90 = 0.5; aspect strength 1 − (angle between downslope and the light's travel)/180°
        assertEquals(1.0, inner(HillshadeMethod.IGOR, WEST_FACING, 270, 45, D), 1e-6, "lit from the west: facing it");
        assertEquals(0.5, inner(HillshadeMethod.IGOR, WEST_FACING, 90, 45, D), 1e-6, "from the east: facing away");
        assertEquals(0.75, inner(HillshadeMethod.IGOR, WEST_FACING, 0, 45, D), 1e-6, "from the north: 90° off");
        assertEquals(0.75, inner(HillshadeMethod.IGOR, WEST_FACING, 180, 45, D), 1e-6, "from the south: 90° off");
        assertEquals(1 - 0.5 * (1 - 45.0 / 180), inner(HillshadeMethod.IGOR, WEST_FACING, 45, 45, D), 1e-6,
                "from the north-east: 45° off facing away");
        assertEquals(inner(HillshadeMethod.IGOR, WEST_FACING, 90, 45, D),
                inner(HillshadeMethod.IGOR, WEST_FACING, 90, 5, D), 0f, "the elevation is not used");
        // z = 3: slope atan(3) = 71.57°
        assertEquals(1 - Math.toDegrees(Math.atan(3)) / 90,
                inner(HillshadeMethod.IGOR, WEST_FACING, 90, 45, D.withZFactor(3)), 1e-6, "the z-factor steepens");
    }

    @Test
    void combinedDarkensTheHillshadeByTheSlope() {
        // 1 − incidence · slope / (π/2)²: slope π/4
        assertEquals(1.0, inner(HillshadeMethod.COMBINED, WEST_FACING, 270, 45, D), 1e-6,
                "light along the normal: incidence 0");
        assertEquals(0.5, inner(HillshadeMethod.COMBINED, WEST_FACING, 90, 45, D), 1e-6,
                "light grazing from the east: incidence π/2");
        assertEquals(1 - (3 * Math.PI / 4) * (Math.PI / 4) / (Math.PI * Math.PI / 4),
                inner(HillshadeMethod.COMBINED, WEST_FACING, 90, 0, D), 1e-6, "from the east on the horizon: 3π/4");
        Dem flat = SyntheticDems.flat(5, 5, 30, 100);
        for (float v : illuminate(HillshadeMethod.COMBINED.stage(D), flat, new LightDirection(10, 5))) {
            assertEquals(1f, v, 1e-6f, "flat ground is white under any light");
        }
    }

    @Test
    void grayBytesAreGdaldemsAndNeverNoDataForAValidCell() {
        assertEquals(0, HillshadeMethod.IGOR.gray(Float.NaN, D));
        assertEquals(255, HillshadeMethod.IGOR.gray(1f, D));
        assertEquals(128, HillshadeMethod.IGOR.gray(0.5f, D)); // 127.5 → 128 (ties to even)
        assertEquals(1, HillshadeMethod.IGOR.gray(0.001f, D)); // gdaldem: 0, its no-data
        assertEquals(0, HillshadeMethod.COMBINED.gray(Float.NaN, D));
        assertEquals(255, HillshadeMethod.COMBINED.gray(1f, D));
        assertEquals(128, HillshadeMethod.COMBINED.gray(0.5f, D)); // 1 + 127
        assertEquals(1, HillshadeMethod.COMBINED.gray(-0.2f, D));
        for (float v = -1; v <= 1; v += 0.01f) {
            int g = HillshadeMethod.COMBINED.gray(v, D);
            assertTrue(g >= 1 && g <= 255, v + " → " + g);
        }
    }
}
