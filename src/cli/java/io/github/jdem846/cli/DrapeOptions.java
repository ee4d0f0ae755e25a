package io.github.jdem846.cli;

import io.github.jdem846.drape.Drape;
import io.github.jdem846.render.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code --drape IMAGE}, repeatable: georeferenced images laid over the tint before the light ({@link Drape}).
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class DrapeOptions {

    @Option(names = "--drape", paramLabel = "IMAGE",
            description = "Drape a georeferenced image over the relief in place of the tint: an 8-bit RGB(A) or gray"
                    + " GeoTIFF, or a PNG or JPEG with a world file (.pgw, .jgw, .wld; CRS from its .prj or .aux.xml,"
                    + " else the DEM's). Sampled bilinearly at each cell, its alpha over the tint, then lit; "
                    + "repeatable, each over the ones before.")
    List<Path> images = new ArrayList<>();

    /**
     * The scene with the images draped, or unchanged without any.
     *
     * @param scene the scene of the other options
     * @return the scene to render
     * @throws IOException when an image is missing or cannot be draped (one line naming it)
     */
    Scene apply(Scene scene) throws IOException {
        return images.isEmpty() ? scene : scene.withDrape(Drape.of(images));
    }
}
