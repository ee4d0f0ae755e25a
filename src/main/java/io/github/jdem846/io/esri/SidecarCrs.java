package io.github.jdem846.io.esri;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.io.source.RegularFiles;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The CRS of an ESRI-family raster: its {@code .prj} when there is one (ESRI WKT, parsed by Apache SIS, or the old
 * ArcInfo keyword format of USGS NED grids, {@link ArcInfoPrj});
 * otherwise, when the extent fits in ±180°/±90° with cells of at most 1, geographic WGS 84 flagged as
 * {@linkplain CrsInfo#asAssumed() assumed}; otherwise unknown.
 */
public final class SidecarCrs {

    private SidecarCrs() {
    }

    /**
     * The {@code .prj} beside {@code dataFile} (same base name; ".prj" or ".PRJ"), or null. It may be something
     * other than a regular file (see {@link RegularFiles}).
     */
    public static Path prjOf(Path dataFile) {
        String name = dataFile.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        for (String ext : new String[] {".prj", ".PRJ", ".Prj"}) {
            Path p = dataFile.resolveSibling(base + ext);
            if (Files.exists(p) && !Files.isDirectory(p)) {
                return p;
            }
        }
        return null;
    }

    /**
     * Resolves the CRS.
     *
     * @param dataFile the raster file (its sibling .prj is looked for)
     * @param layout   the grid (for the assumption rule)
     * @param notices  where to say what was assumed or could not be parsed
     */
    static CrsInfo resolve(Path dataFile, EsriGridLayout layout, List<String> notices) {
        Path prj = prjOf(dataFile);
        String kind = prj != null ? RegularFiles.otherKind(prj) : null;
        if (kind != null) {
            // a FIFO or device: reading it could block
            notices.add(prj.getFileName() + " is " + kind + ", not a regular file, and was not read, so the CRS is"
                    + " unknown");
            return CrsInfo.UNKNOWN;
        }
        if (prj != null) {
            try {
                String text = Files.readString(prj, StandardCharsets.ISO_8859_1);
                if (ArcInfoPrj.looksLikeOne(text)) {
                    return ArcInfoPrj.parse(text, prj.getFileName().toString(), notices);
                }
                return CrsResolver.fromWkt(text);
            } catch (IOException | IllegalArgumentException e) {
                notices.add(prj.getFileName() + " could not be parsed, so the CRS is unknown: " + e.getMessage());
                return CrsInfo.UNKNOWN;
            }
        }
        return assumeFromExtent(layout, "no .prj file", notices);
    }

    /** Geographic WGS 84 (assumed) when the extent and cell size look like degrees; unknown otherwise. */
    public static CrsInfo assumeFromExtent(EsriGridLayout g, String why, List<String> notices) {
        double west = g.originX();
        double east = g.originX() + g.cols() * g.cellWidth();
        double north = g.originY();
        double south = g.originY() - g.rows() * g.cellHeight();
        boolean degrees = west >= -180 - 1e-9 && east <= 180 + 1e-9 && south >= -90 - 1e-9 && north <= 90 + 1e-9
                && g.cellWidth() <= 1 && g.cellHeight() <= 1;
        if (degrees) {
            notices.add(why + ": assumed geographic WGS 84, because the extent fits in ±180°/±90° and cells are at"
                    + " most 1 unit");
            return CrsInfo.WGS84.asAssumed();
        }
        notices.add(why + ": the CRS is unknown, so cell sizes in metres are unknown");
        return CrsInfo.UNKNOWN;
    }

    /** Lower-case extension of a file name without the dot, or "". */
    public static String extension(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(dot + 1).toLowerCase(Locale.ROOT) : "";
    }

    /** The sibling of {@code file} with the same base name and extension {@code ext} in any common case. */
    public static Path sibling(Path file, String ext) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        for (String e : new String[] {ext.toLowerCase(Locale.ROOT), ext.toUpperCase(Locale.ROOT)}) {
            Path p = file.resolveSibling(base + "." + e);
            if (Files.exists(p)) {
                return p;
            }
        }
        return file.resolveSibling(base + "." + ext.toLowerCase(Locale.ROOT));
    }
}
