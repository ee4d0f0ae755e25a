package io.github.jdem846.overlay;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Per-feature style (simplestyle-spec properties) over the file's style: the rules of {@link FeatureStyle#over},
 * and the hand-made features of {@code testdata/overlay/styled_test_features.geojson} drawn on a 40 × 40 grid of
 * 1/64° cells, every pixel whose colour follows from the geometry alone (fully inside or fully outside a shape)
 * predicted by hand; the shapefiles {@code ogr2ogr} made of it (field names cut to 10 characters) draw the same.
 */
class FeatureStyleTest {

    static final Path DIR = Path.of("testdata/overlay");
    static final int N = 40;
    static final int GRAY = 0xff808080;
    /** The file's style: magenta strokes 0 px wide, opaque green fill, points of radius 3. */
    static final OverlayStyle FILE = new OverlayStyle(Color.MAGENTA, 0, Color.GREEN, 3);

    @TempDir
    Path dir;

    static GridGeometry grid() {
        return new GridGeometry(N, N, 10, 50, 1 / 64.0, 1 / 64.0, CrsInfo.WGS84, PixelAnchor.CORNER);
    }

    static int[] paint(List<Overlay> overlays) {
        int[] argb = new int[N * N];
        Arrays.fill(argb, GRAY);
        OverlayPainter.of(overlays, grid()).paintRows(argb, 0, N);
        return argb;
    }

    /** Source over an opaque gray pixel, as the equation says (0..255 channels). */
    static int over(int rgb, int alpha) {
        int out = 0xff000000;
        for (int shift = 0; shift <= 16; shift += 8) {
            double s = (rgb >> shift) & 0xff;
            double d = (GRAY >> shift) & 0xff;
            out |= (int) Math.round(s * alpha / 255.0 + d * (1 - alpha / 255.0)) << shift;
        }
        return out;
    }

    /** The expected colour of each pixel, or 0 where a shape's edge crosses it (not predicted). */
    static int[] expected() {
        int[] e = new int[N * N];
        Arrays.fill(e, GRAY);
        rect(e, 2, 2, 10, 10, 0xffff0000);               // opaque red fill
        rect(e, 12, 2, 20, 10, over(0x0000ff, 128));     // blue at 0.5: alpha 128
        rect(e, 22, 2, 30, 10, 0xff00ff00);              // no properties: the file's green
        rect(e, 31, 2, 39, 10, over(0x00ff00, 64));      // the file's green at 0.25: alpha 64
        // a 2 px black outline on the edges of columns 2..9, rows 18..25, over the file's green fill
        rect(e, 2, 18, 10, 26, 0xff00ff00);
        for (int r = 17; r <= 26; r++) {
            for (int c = 1; c <= 10; c++) {
                boolean edgeBand = r >= 19 && r <= 24 && (c == 1 || c == 2 || c == 9 || c == 10)
                        || c >= 3 && c <= 8 && (r == 17 || r == 18 || r == 25 || r == 26);
                boolean corner = (r <= 18 || r >= 25) && (c <= 2 || c >= 9);
                if (edgeBand) {
                    e[r * N + c] = 0xff000000;
                } else if (corner) {
                    e[r * N + c] = 0; // round joins: partly covered
                }
            }
        }
        // a yellow line 2 px wide along y = 14 from x = 4 to 16 (round caps: columns 3 and 16 partly)
        rect(e, 4, 13, 16, 15, 0xffffff00);
        rect(e, 3, 13, 4, 15, 0);
        rect(e, 16, 13, 17, 15, 0);
        // a white line at half, 4 px wide, along y = 14 from x = 22 to 36 (caps of radius 2)
        rect(e, 22, 12, 36, 16, over(0xffffff, 128));
        rect(e, 20, 12, 22, 16, 0);
        rect(e, 36, 12, 38, 16, 0);
        disc(e, 10, 32, 5, 0xff00ffff);                  // large cyan marker: radius 5
        disc(e, 30.5, 30.5, 3, 0xffff00ff);              // the file's point: radius 3, the stroke's magenta
        return e;
    }

    static void rect(int[] e, int c0, int r0, int c1, int r1, int argb) {
        for (int r = r0; r < r1; r++) {
            for (int c = c0; c < c1; c++) {
                e[r * N + c] = argb;
            }
        }
    }

    static void disc(int[] e, double x, double y, double radius, int argb) {
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                double far = 0;
                for (int corner = 0; corner < 4; corner++) {
                    far = Math.max(far, Math.hypot(c + (corner & 1) - x, r + (corner >> 1) - y));
                }
                double near = Math.hypot(Math.max(0, Math.max(c - x, x - c - 1)), Math.max(0, Math.max(r - y,
                        y - r - 1)));
                if (far <= radius) {
                    e[r * N + c] = argb;
                } else if (near < radius + 1e-9) {
                    e[r * N + c] = 0;
                }
            }
        }
    }

    static void assertPredicted(int[] argb) {
        int[] e = expected();
        int checked = 0;
        for (int i = 0; i < N * N; i++) {
            if (e[i] == 0) {
                continue;
            }
            checked++;
            for (int shift = 0; shift <= 24; shift += 8) {
                int want = (e[i] >>> shift) & 0xff;
                int got = (argb[i] >>> shift) & 0xff;
                assertTrue(Math.abs(want - got) <= 1, String.format("pixel (%d, %d): expected %08x, got %08x",
                        i % N, i / N, e[i], argb[i]));
            }
        }
        assertTrue(checked > N * N * 9 / 10, checked + " pixels predicted");
    }

    @Test
    void everyPredictedPixelOfTheGeoJsonFeaturesHasItsColour() throws IOException {
        Overlay o = OverlayFiles.read(DIR.resolve("styled_test_features.geojson"), FILE);
        assertEquals(9, o.geometries().size());
        assertPredicted(paint(List.of(o)));
    }

    @Test
    void theShapefilesOgr2ogrMadeDrawTheSamePixels() throws IOException {
        List<Overlay> fromShp = List.of(read("polygons"), read("lines"), read("points"));
        List<Overlay> fromJson = List.of(only("Polygon"), only("LineString"), only("Point"));
        int[] shp = paint(fromShp);
        assertPredicted(shp);
        assertArrayEquals(paint(fromJson), shp);
    }

    private static Overlay read(String kind) throws IOException {
        return OverlayFiles.read(DIR.resolve("styled_test_features_" + kind + ".shp"), FILE);
    }

    private static Overlay only(String type) throws IOException {
        Overlay all = OverlayFiles.read(DIR.resolve("styled_test_features.geojson"), FILE);
        List<Integer> keep = java.util.stream.IntStream.range(0, all.geometries().size())
                .filter(i -> all.geometries().get(i).getGeometryType().equals(type)).boxed().toList();
        return new Overlay(all.name(), keep.stream().map(all.geometries()::get).toList(), all.crs(), FILE,
                keep.stream().map(all.featureStyles()::get).toList());
    }

    @Test
    void propertiesOverrideTheFileStyleOneByOne() {
        OverlayStyle noFill = new OverlayStyle(new Color(10, 20, 30, 200), 1.5, null, 3);
        assertEquals(noFill, FeatureStyle.of(Map.of("name", "x", "title", "y")).over(noFill));
        OverlayStyle s = FeatureStyle.of(Map.of("stroke", "#f00", "stroke-width", 4, "fill", "#00ff00")).over(noFill);
        assertEquals(new Color(255, 0, 0, 200), s.stroke(), "the file's stroke alpha kept");
        assertEquals(4, s.width());
        assertEquals(new Color(0, 255, 0, 153), s.fill(), "no fill opacity anywhere: simplestyle's 0.6");
        assertEquals(s.stroke(), s.pointPaint(), "points take the stroke colour without marker-color");
        OverlayStyle filled = new OverlayStyle(Color.BLACK, 1, new Color(0, 0, 255, 80), 3);
        assertEquals(new Color(255, 255, 0, 80), FeatureStyle.of(Map.of("fill", "#ffff00")).over(filled).fill(),
                "the file's fill alpha kept");
        assertNull(FeatureStyle.of(Map.of("fill-opacity", 0.3)).over(noFill).fill(), "opacity of no fill: none");
        OverlayStyle m = FeatureStyle.of(Map.of("marker-color", "#0000ff", "marker-size", "small",
                "stroke-opacity", "0.5")).over(noFill);
        assertEquals(new Color(0, 0, 255, 128), m.pointPaint());
        assertEquals(2, m.pointRadius());
        assertEquals(new Color(10, 20, 30, 128), m.stroke());
        assertEquals(7.5, FeatureStyle.of(Map.of("marker-size", "7.5")).over(noFill).pointRadius());
        assertEquals(noFill, FeatureStyle.of(Map.of("stroke", "", "stroke-width", " ")).over(noFill),
                "blank values are absent");
    }

    @Test
    void aBadStylePropertyNamesTheFileTheFeatureAndTheProperty() throws IOException {
        assertThrows(IllegalArgumentException.class, () -> FeatureStyle.of(Map.of("stroke-opacity", 1.5)));
        assertThrows(IllegalArgumentException.class, () -> FeatureStyle.of(Map.of("stroke-width", -1)));
        assertThrows(IllegalArgumentException.class, () -> FeatureStyle.of(Map.of("marker-size", "huge")));
        Path bad = dir.resolve("bad.geojson");
        Files.writeString(bad, "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"properties\":"
                + "{},\"geometry\":{\"type\":\"Point\",\"coordinates\":[10,50]}},{\"type\":\"Feature\",\"properties\":"
                + "{\"stroke\":\"banana\"},\"geometry\":{\"type\":\"Point\",\"coordinates\":[10,50]}}]}");
        OverlayFileException e = assertThrows(OverlayFileException.class, () -> OverlayFiles.read(bad, FILE));
        assertTrue(e.getMessage().startsWith(bad + ": feature 2: property stroke: colour 'banana' is not #RGB, "
                + "#RRGGBB"), e.getMessage());
    }
}
