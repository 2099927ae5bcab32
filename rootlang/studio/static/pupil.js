// The first page a pupil sees in a class: their name, which picks their own folder. The studio
// answers with a cookie; the studio page (the same address) then opens in that folder.
import {api, setWords, translate} from "./classapi.js";

const $ = id => document.getElementById(id);

async function start() {
  const who = await api("GET", "/api/pupil");
  setWords(who.strings);
  document.documentElement.lang = who.language;
  translate(document);
  $("join").addEventListener("submit", async event => {
    event.preventDefault();
    $("problem").textContent = "";
    try {
      await api("POST", "/api/pupil", {name: $("name").value});
      location.reload();   // the studio page, in this pupil's folder (?open= and ?language= stay)
    } catch (error) {
      $("problem").textContent = error.message;
    }
  });
}

start().catch(error => { $("problem").textContent = error.message; });
