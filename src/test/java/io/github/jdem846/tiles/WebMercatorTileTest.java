package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.geo.WebMercator;
import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * Tile arithmetic against published values (the OpenStreetMap wiki's "Slippy map tilenames": zoom 0 covers
 * 360° × 170.1022°, zoom 1 tiles 180° × 85.0511°; the Web Mercator world half-width and zoom-0 resolution given by
 * every tiling library; the PMTiles v3 spec's table of tile IDs) and against the wiki's own formulas, written here
 * independently: n = 2^z, x = ⌊(λ + 180)/360 · n⌋, y = ⌊(1 − ln(tan φ + sec φ)/π)/2 · n⌋, and back
 * λ = x/n · 360 − 180, φ = atan(sinh(π(1 − 2y/n))).
 */
class WebMercatorTileTest {

    private static int wikiX(double lon, int z) {
        return (int) Math.floor((lon + 180) / 360 * (1 << z));
    }

    private static int wikiY(double lat, int z) {
        double r = Math.toRadians(lat);
        return (int) Math.floor((1 - Math.log(Math.tan(r) + 1 / Math.cos(r)) / Math.PI) / 2 * (1 << z));
    }

    private static double wikiLon(int x, int z) {
        return x / (double) (1 << z) * 360 - 180;
    }

    private static double wikiLat(int y, int z) {
        return Math.toDegrees(Math.atan(Math.sinh(Math.PI * (1 - 2.0 * y / (1 << z)))));
    }

    @Test
    void worldConstantsAreTheKnownOnes() {
        assertEquals(20037508.342789244, WebMercator.HALF_WORLD, 1e-6);
        assertEquals(85.0511287798066, WebMercator.MAX_LATITUDE, 1e-12);
        assertEquals(156543.03392804097, WebMercatorTile.pixelSize(0), 1e-8);
        assertEquals(39135.75848201024, WebMercatorTile.pixelSize(2), 1e-8);
        assertEquals(WebMercator.HALF_WORLD, WebMercator.y(WebMercator.MAX_LATITUDE), 1e-6);
        assertEquals(WebMercator.HALF_WORLD, WebMercator.y(90), 1e-6, "the pole clamps to the world's edge");
    }

    @Test
    void zoomZeroAndOneCoverTheWikisDegrees() {
        LatLonBox world = new WebMercatorTile(0, 0, 0).latLonBounds();
        assertEquals(360, world.east() - world.west(), 1e-9);
        assertEquals(170.1022, world.north() - world.south(), 1e-4, "the wiki truncates to 4 decimals");
        LatLonBox nw = new WebMercatorTile(1, 0, 0).latLonBounds();
        assertEquals(-180, nw.west(), 1e-9);
        assertEquals(0, nw.east(), 1e-9);
        assertEquals(85.0511, nw.north(), 1e-4);
        assertEquals(0, nw.south(), 1e-9);
        WebMercatorTile first = new WebMercatorTile(1, 0, 0);
        assertEquals(-WebMercator.HALF_WORLD, first.westX(), 1e-6);
        assertEquals(WebMercator.HALF_WORLD, first.northY(), 1e-6);
        assertEquals(0, first.southY(), 1e-6);
        assertEquals(0, first.eastX(), 1e-6);
    }

    @Test
    void knownPlacesFallInTheirKnownTiles() {
        // London at zoom 10 is OSM tile 10/511/340; the PMTiles spec's example tile 12/3423/1763 lies in central
        // Taiwan (120.85° to 120.94° E, 24.21° to 24.29° N)
        assertEquals(new WebMercatorTile(10, 511, 340), WebMercatorTile.containing(51.5074, -0.1278, 10));
        assertEquals(new WebMercatorTile(12, 3423, 1763), WebMercatorTile.containing(24.25, 120.9, 12));
        // Null Island sits on the corner of four tiles and belongs to the one south-east of it
        assertEquals(new WebMercatorTile(3, 4, 4), WebMercatorTile.containing(0, 0, 3));
        // beyond the world: clamped to the edge rows, longitudes wrapped
        assertEquals(new WebMercatorTile(4, 0, 0), WebMercatorTile.containing(89.9, -180, 4));
        assertEquals(new WebMercatorTile(4, 0, 15), WebMercatorTile.containing(-89.9, 180, 4));
        assertEquals(WebMercatorTile.containing(10, -170, 6), WebMercatorTile.containing(10, 190, 6));
    }

    @Test
    void agreesWithTheWikiFormulasEverywhere() {
        Random r = new Random(846);
        for (int i = 0; i < 20000; i++) {
            int z = r.nextInt(WebMercatorTile.MAX_ZOOM + 1);
            double lat = (r.nextDouble() * 2 - 1) * 85;
            double lon = (r.nextDouble() * 2 - 1) * 179.999;
            WebMercatorTile t = WebMercatorTile.containing(lat, lon, z);
            assertEquals(wikiX(lon, z), t.x(), () -> lat + ", " + lon + " at " + z);
            assertEquals(wikiY(lat, z), t.y(), () -> lat + ", " + lon + " at " + z);
            LatLonBox b = t.latLonBounds();
            assertEquals(wikiLon(t.x(), z), b.west(), 1e-9);
            assertEquals(wikiLon(t.x() + 1, z), b.east(), 1e-9);
            assertEquals(wikiLat(t.y(), z), b.north(), 1e-9);
            assertEquals(wikiLat(t.y() + 1, z), b.south(), 1e-9);
            assertTrue(b.west() <= lon && lon < b.east() && b.south() < lat && lat <= b.north(),
                    () -> t + " " + b + " should hold " + lat + ", " + lon);
        }
    }

    @Test
    void metresAndDegreesRoundTrip() {
        Random r = new Random(3857);
        for (int i = 0; i < 10000; i++) {
            double lat = (r.nextDouble() * 2 - 1) * WebMercator.MAX_LATITUDE;
            double lon = (r.nextDouble() * 2 - 1) * 180;
            assertEquals(lat, WebMercator.latitude(WebMercator.y(lat)), 1e-10);
            assertEquals(lon, WebMercator.longitude(WebMercator.x(lon)), 1e-10);
        }
        // tiles share edges: a tile's south edge is the next row's north edge, parents hold their children
        WebMercatorTile t = new WebMercatorTile(9, 135, 199);
        assertEquals(t.southY(), new WebMercatorTile(9, 135, 200).northY(), 0);
        assertEquals(new WebMercatorTile(8, 67, 99), t.parent());
        assertEquals(512 - 1 - 199, t.tmsY());
        assertEquals(t.eastX() - t.westX(), WebMercatorTile.SIZE * WebMercatorTile.pixelSize(9), 1e-6);
    }

    @Test
    void rangesCoverExactlyTheTilesABoxOverlaps() {
        Random r = new Random(11);
        for (int i = 0; i < 300; i++) {
            int z = 3 + r.nextInt(8);
            double w = -170 + r.nextDouble() * 330;
            double s = -80 + r.nextDouble() * 150;
            LatLonBox box = new LatLonBox(s, Math.min(85, s + r.nextDouble() * 3), w, w + r.nextDouble() * 4);
            TileRange range = TileRange.covering(box, z);
            // an overlap of positive area by the wiki's bounds: a column overlapping in longitude and a row in
            // latitude
            Set<WebMercatorTile> expected = new HashSet<>();
            int n = 1 << z;
            for (int x = 0; x < n; x++) {
                if (wikiLon(x, z) < box.east() && wikiLon(x + 1, z) > box.west()) {
                    for (int y = 0; y < n; y++) {
                        if (wikiLat(y + 1, z) < box.north() && wikiLat(y, z) > box.south()) {
                            expected.add(new WebMercatorTile(z, x, y));
                        }
                    }
                }
            }
            assertEquals(expected, new HashSet<>(range.tiles()), box + " at " + z);
            assertEquals(expected.size(), range.count());
        }
    }

    @Test
    void refusesTilesOutsideTheirZoom() {
        assertThrows(IllegalArgumentException.class, () -> new WebMercatorTile(2, 4, 0));
        assertThrows(IllegalArgumentException.class, () -> new WebMercatorTile(23, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new WebMercatorTile(-1, 0, 0));
        assertEquals(new ZoomRange(0, 12), ZoomRange.parse("0-12"));
        assertEquals(new ZoomRange(10, 10), ZoomRange.parse(" 10 "));
        assertThrows(IllegalArgumentException.class, () -> ZoomRange.parse("12-3"));
        assertThrows(IllegalArgumentException.class, () -> ZoomRange.parse("0-23"));
        assertThrows(IllegalArgumentException.class, () -> ZoomRange.parse("ten"));
    }

    @Test
    void pmtilesIdsFollowTheSpecAndTheHilbertCurve() {
        // the spec's table
        assertEquals(0, PmTiles.tileId(0, 0, 0));
        assertEquals(1, PmTiles.tileId(1, 0, 0));
        assertEquals(2, PmTiles.tileId(1, 0, 1));
        assertEquals(3, PmTiles.tileId(1, 1, 1));
        assertEquals(4, PmTiles.tileId(1, 1, 0));
        assertEquals(5, PmTiles.tileId(2, 0, 0));
        assertEquals(19078479, PmTiles.tileId(12, 3423, 1763));
        // each zoom's IDs are a block after the lower zooms', and consecutive IDs are neighbouring tiles
        for (int z = 0; z <= 6; z++) {
            int n = 1 << z;
            long first = ((1L << (2 * z)) - 1) / 3;
            int[][] at = new int[n * n][];
            for (int x = 0; x < n; x++) {
                for (int y = 0; y < n; y++) {
                    long id = PmTiles.tileId(z, x, y);
                    assertTrue(id >= first && id < first + (long) n * n);
                    assertEquals(null, at[(int) (id - first)], "IDs are unique");
                    at[(int) (id - first)] = new int[] {x, y};
                    assertEquals(z, PmTilesSink.zoomOf(id));
                }
            }
            for (int i = 1; i < at.length; i++) {
                int d = Math.abs(at[i][0] - at[i - 1][0]) + Math.abs(at[i][1] - at[i - 1][1]);
                assertEquals(1, d, "Hilbert steps move to a neighbour at zoom " + z);
            }
        }
    }
}
