package io.github.jdem846.tiles;

import java.nio.file.Path;
import java.util.Locale;

/** How a tile pyramid is stored, chosen from the output's name. */
public enum TileFormat {
    /** {@code DIR/z/x/y.png}: any name without the archive's extension. */
    DIRECTORY,
    /** One PMTiles v3 archive: a name ending in {@code .pmtiles}. */
    PMTILES;

    /**
     * The format for {@code output}.
     *
     * @param output the archive's or directory's path
     * @return {@link #PMTILES} for a {@code .pmtiles} name, else the directory format
     * @throws IllegalArgumentException for a {@code .mbtiles} name, which is not written
     */
    public static TileFormat of(Path output) {
        Path name = output.getFileName();
        String n = name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
        if (n.endsWith(".pmtiles")) {
            return PMTILES;
        }
        if (n.endsWith(".mbtiles")) {
            throw new IllegalArgumentException("'" + output + "': MBTiles archives are not written; name a "
                    + ".pmtiles archive or a directory for z/x/y.png tiles");
        }
        return DIRECTORY;
    }
}
