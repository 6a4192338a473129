//! The OBJ/MTL loader, the glTF loader (JSON or GLB bytes) and the TOML
//! scene-file parser on arbitrary input: typed errors, never panics;
//! accepted scenes validate.
#![no_main]

use libfuzzer_sys::fuzz_target;
use slc_scene::gltf::GltfScene;
use slc_scene::scene::Scene;
use slc_scene::scene_file::SceneFile;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    // First byte chooses the loader; an OBJ's MTL is the text after a NUL,
    // a glTF's external buffers are the bytes after the first NUL.
    let Some((&which, rest)) = data.split_first() else { return };
    if which % 3 == 2 {
        let (file, bin) = match rest.iter().position(|&b| b == 0) {
            Some(i) => (&rest[..i], Some(rest[i + 1..].to_vec())),
            None => (rest, None),
        };
        if let Ok(g) = GltfScene::parse(file, "fuzz.gltf", |_| bin.clone()) {
            g.scene.validate().expect("a loaded glTF scene validates");
        }
    } else if which % 3 == 0 {
        let (obj, mtl) = match rest.iter().position(|&b| b == 0) {
            Some(i) => (&rest[..i], Some(rest[i + 1..].to_vec())),
            None => (rest, None),
        };
        if let Ok(scene) = Scene::parse_obj(obj, "fuzz.obj", |_| mtl.clone()) {
            scene.validate().expect("a loaded scene validates");
        }
    } else if let Ok(text) = std::str::from_utf8(rest) {
        // Relative paths resolve into a folder that does not exist.
        if let Ok(f) = SceneFile::parse(text, Path::new("/nonexistent-slc-fuzz"), "fuzz.toml") {
            f.scene.validate().expect("a loaded scene file validates");
        }
    }
});
