package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.UtmZone;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.util.Locale;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The notice of how cells are measured: a Web Mercator grid measured on the ground says so (and nothing when measured
 * in map metres, as asked); another projection gets a notice when its scale factor at the grid's centre departs
 * from 1 by more than 2 %, whether the CRS came with its Apache SIS object or as a UTM zone known by its code; a
 * scene whose stages do not use the cells' size in metres gets none.
 */
class ScaleNoticeTest {

    @Test
    void aWebMercatorGridMeasuredOnTheGroundSaysSo() throws IOException {
        for (String ext : new String[] {".tif", ".flt"}) {
            GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VANCOUVER + ext)).geometry();
            GridGeometry ground = MercatorScale.GROUND.apply(g);
            String notice = ScaleNotice.of(ground).orElseThrow();
            int row = g.height() / 2;
            assertTrue(notice.startsWith(String.format(Locale.ROOT, "Web Mercator grid: slopes and shadow lengths "
                    + "use the cells' ground size, row by row (%.1f m instead of %.1f map metres at the centre, "
                    + "%.2f° N)", ground.cellWidthMeters(row), g.cellWidth(),
                    WebMercator.latitude(g.centerY(row)))), notice);
            // the scale factor agrees: map metres over ground metres at the centre
            double k = g.groundScaleFactor().orElseThrow();
            assertEquals(k, g.cellWidth() / ground.cellWidthMeters(row), 2e-3 * k);
            assertEquals(Optional.empty(), ScaleNotice.of(MercatorScale.MAP.apply(g)), ext + ": map metres asked");
        }
    }

    @Test
    void theNoticeNamesWhatTheSceneMeasures() throws IOException {
        GridGeometry ground = MercatorScale.GROUND.apply(DemReader.inspect(TestDems.DEM_DIR.resolve(
                TestDems.VANCOUVER + ".tif")).geometry());
        Scene hillshade = Scene.defaults().withTint(null);
        assertTrue(ScaleNotice.of(ground, hillshade).orElseThrow().startsWith("Web Mercator grid: slopes use"));
        Scene shadows = hillshade.withHillshade(null).withShadows(ShadowAlgorithm.SWEEP);
        assertTrue(ScaleNotice.of(ground, shadows).orElseThrow().startsWith("Web Mercator grid: shadow lengths use"));
        Scene fixedScale = hillshade.withHillshadeOptions(HillshadeOptions.DEFAULTS.withHorizontalScale(0.66));
        assertEquals(Optional.empty(), ScaleNotice.of(ground, fixedScale));
        assertEquals(Optional.empty(), ScaleNotice.of(ground, Scene.defaults().withHillshade(null)));
    }

    @Test
    void aUtmGridNearItsCentralMeridianGetsNone() throws IOException {
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".tif")).geometry();
        assertEquals(Optional.empty(), ScaleNotice.of(g));
    }

    @Test
    void aUtmGridFarFromItsCentralMeridianGetsTheExactNotice() {
        // 1 350 km east of the central meridian the scale is about 1.022; at 1 200 km about 1.017: between the
        // spherical screen's 1.5 % and the notice's 2 %, so decided by Apache SIS's exact value.
        CrsInfo zone = UtmZone.ofEpsg(32611).orElseThrow().crsInfo();
        GridGeometry far = grid(zone, 1_350_000);
        double k = far.groundScaleFactor().orElseThrow();
        assertTrue(k > 1.02 && k < 1.025, "k = " + k);
        String notice = ScaleNotice.of(far).orElseThrow();
        assertTrue(notice.contains(String.format(java.util.Locale.ROOT, "%.3f", k)), notice);

        GridGeometry between = grid(zone, 1_200_000);
        double kb = between.groundScaleFactor().orElseThrow();
        assertTrue(kb > 1.015 && kb < 1.02, "k = " + kb);
        assertEquals(Optional.empty(), ScaleNotice.of(between));
    }

    /** 100 × 100 cells of 30 m centred {@code dx} east of the zone's central meridian, at 4 000 km north. */
    private static GridGeometry grid(CrsInfo crs, double dx) {
        return new GridGeometry(100, 100, UtmZone.FALSE_EASTING + dx - 1500, 4_001_500, 30, 30, crs,
                PixelAnchor.CORNER);
    }
}
